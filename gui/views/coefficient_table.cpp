#include "views/coefficient_table.h"

#include <QComboBox>
#include <QHeaderView>
#include <QLabel>
#include <QTableWidget>
#include <QVBoxLayout>

namespace oflab {

CoefficientTable::CoefficientTable(QWidget* parent) : QWidget(parent) {
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->addWidget(new QLabel(tr("Coefficients at the principal point"), this));
  basis_box_ = new QComboBox(this);
  basis_box_->setObjectName(QStringLiteral("coefficient_basis"));
  for (int k = 0; k < kBasisKindCount; ++k) {
    basis_box_->addItem(QString::fromUtf8(basis_title(static_cast<BasisKind>(k))));
  }
  basis_box_->setCurrentIndex(static_cast<int>(BasisKind::kPlanar));
  layout->addWidget(basis_box_);
  table_ = new QTableWidget(0, 3, this);
  table_->setObjectName(QStringLiteral("coefficient_table"));
  table_->setHorizontalHeaderLabels({tr("Term"), tr("Value"), tr("Unit")});
  table_->verticalHeader()->hide();
  table_->setEditTriggers(QAbstractItemView::NoEditTriggers);
  table_->horizontalHeader()->setStretchLastSection(true);
  layout->addWidget(table_, 1);
  connect(basis_box_, QOverload<int>::of(&QComboBox::currentIndexChanged), this,
          [this](int) { refill(); });
}

void CoefficientTable::show_terms(const TaylorTerms& flow, double radius_px) {
  flow_ = flow;
  radius_px_ = radius_px;
  refill();
}

BasisKind CoefficientTable::basis() const {
  return static_cast<BasisKind>(basis_box_->currentIndex());
}

void CoefficientTable::set_basis(BasisKind kind) {
  basis_box_->setCurrentIndex(static_cast<int>(kind));
}

QString CoefficientTable::value_text(int row) const {
  const QTableWidgetItem* item = row < table_->rowCount() ? table_->item(row, 1) : nullptr;
  return item ? item->text() : QString();
}

void CoefficientTable::refill() {
  const std::vector<BasisTerm> terms = basis_terms(basis());
  // Rebuild the rows only when the basis changes; while the motion plays only the value
  // cells change (re-laying out the whole table every frame costs more than rendering).
  const bool rebuild = table_->rowCount() != static_cast<int>(terms.size()) ||
                       shown_basis_ != static_cast<int>(basis());
  if (rebuild) {
    table_->setRowCount(static_cast<int>(terms.size()));
    for (int row = 0; row < table_->rowCount(); ++row) {
      const BasisTerm& term = terms[static_cast<size_t>(row)];
      const QStringList cells = {QString::fromStdString(term.symbol), QString(),
                                 QString::fromUtf8(order_unit(term.order))};
      for (int col = 0; col < 3; ++col) {
        auto* item = new QTableWidgetItem(cells[col]);
        item->setToolTip(QString::fromStdString(term.description));
        if (col == 1) item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
        table_->setItem(row, col, item);
      }
    }
    shown_basis_ = static_cast<int>(basis());
  }
  const QColor normal = palette().color(QPalette::Active, QPalette::Text);
  const QColor muted = palette().color(QPalette::Disabled, QPalette::Text);
  for (int row = 0; row < table_->rowCount(); ++row) {
    const BasisTerm& term = terms[static_cast<size_t>(row)];
    const double value = term.coefficient(flow_);
    const bool zero = is_negligible(term.order, value, radius_px_);
    const QString shown = zero ? QStringLiteral("0") : QString::number(value, 'g', 5);
    if (table_->item(row, 1)->text() != shown) table_->item(row, 1)->setText(shown);
    for (int col = 0; col < 3; ++col) {
      QTableWidgetItem* item = table_->item(row, col);
      if (item->foreground().color() != (zero ? muted : normal)) {
        item->setForeground(zero ? muted : normal);
      }
    }
  }
  if (rebuild) table_->resizeColumnsToContents();
}

}  // namespace oflab

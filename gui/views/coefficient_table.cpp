#include "views/coefficient_table.h"

#include <QComboBox>
#include <QEvent>
#include <QHeaderView>
#include <QLabel>
#include <QScrollBar>
#include <QTableWidget>
#include <QVBoxLayout>
#include <algorithm>

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
  basis_box_->setToolTip(tr("The basis the coefficients are given in (dissertation Fig. 14-16)"));
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
        item->setToolTip(
            tr("%1: %2, in %3").arg(cells[0], QString::fromStdString(term.description), cells[2]));
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
  if (rebuild) fit_columns();
}

void CoefficientTable::fit_columns() {
  const QFontMetrics fm(table_->font());
  table_->resizeColumnsToContents();
  table_->resizeRowsToContents();
  // Values are written with 5 significant digits ('g'): these are the widest such texts.
  int widest = 0;
  for (const QString& v : {QStringLiteral("-0.00088888"), QStringLiteral("-8.8888e+88")}) {
    widest = std::max(widest, fm.horizontalAdvance(v));
  }
  const int padding = 2 * fm.averageCharWidth() + 8;  // the item's margins and focus frame
  table_->setColumnWidth(1, std::max(table_->columnWidth(1), widest + padding));
  int width = 2 * table_->frameWidth() + table_->verticalScrollBar()->sizeHint().width();
  for (int col = 0; col < table_->columnCount(); ++col) width += table_->columnWidth(col);
  table_->setMinimumWidth(width);
}

void CoefficientTable::changeEvent(QEvent* event) {
  QWidget::changeEvent(event);
  if (event->type() == QEvent::FontChange && table_) fit_columns();
}

}  // namespace oflab

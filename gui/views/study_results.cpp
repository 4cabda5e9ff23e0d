// The study window's results (gui/views/study_window.h): the results page, its table and
// psychometric plot, the class view of many observers' CSVs and the CSV written.
#include <QFileDialog>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPainter>
#include <QPainterPath>
#include <QPushButton>
#include <QStackedWidget>
#include <QTableWidget>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>
#include <set>

#include "adapters/paint_helpers.h"
#include "display/palette.h"
#include "formats/atomic_file.h"
#include "views/study_window.h"

namespace oflab {
namespace {

QString text_of(double v, int decimals) { return QString::number(v, 'f', decimals); }

// A value and its interval: "0.84 (0.61-1.20)".
QString interval_text(double t, double low, double high) {
  return QStringLiteral("%1 (%2-%3)").arg(text_of(t, 2), text_of(low, 2), text_of(high, 2));
}

}  // namespace

// The proportion correct against the shown error (log scale) per condition: the answers
// grouped in eight bins of the error range (a dot's area by its count) and the fitted
// Weibull with the study's assumed slope and lapse, its threshold marked; proportions from 0
// (a 2AFC observer guesses 0.5, a bin of a few answers may fall below it) to 1.
class PsychometricPlot : public QWidget {
 public:
  explicit PsychometricPlot(QWidget* parent) : QWidget(parent) { setMinimumSize(480, 300); }
  void set(const Study& study, std::vector<TrialRow> rows, std::vector<ThresholdResult> fits) {
    study_ = study, rows_ = std::move(rows), fits_ = std::move(fits);
    update();
  }

 protected:
  void paintEvent(QPaintEvent*) override;

 private:
  Study study_;
  std::vector<TrialRow> rows_;
  std::vector<ThresholdResult> fits_;
  QPointF at(const QRectF& box, double px, double p) const {
    const double u = std::log(px / study_.min_px) / std::log(study_.max_px / study_.min_px);
    // Proportions 0..1 inside a margin of 3 % of the box's height at each end.
    return {box.left() + std::clamp(u, 0.0, 1.0) * box.width(),
            box.bottom() - (0.03 + 0.94 * p) * box.height()};
  }
  void paint_axes(QPainter& p, const QRectF& box) const;
  void paint_condition(QPainter& p, const QRectF& box, size_t c) const;
};

void PsychometricPlot::paintEvent(QPaintEvent*) {
  QPainter p(this);
  p.setRenderHint(QPainter::Antialiasing);
  p.fillRect(rect(), palette().base());
  if (study_.conditions.empty()) return;
  const int m = fontMetrics().height();
  const QRectF box(4.0 * m, m, width() - 5.0 * m, height() - 4.0 * m);
  paint_axes(p, box);
  for (size_t c = 0; c < study_.conditions.size(); ++c) paint_condition(p, box, c);
}

void PsychometricPlot::paint_axes(QPainter& p, const QRectF& box) const {
  p.setPen(palette().text().color());
  p.drawRect(box);
  for (double v : {0.0, 0.5, 0.75, 1.0}) {
    const QPointF y = at(box, study_.min_px, v);
    p.drawText(QRectF(0, y.y() - 10, box.left() - 6, 20), Qt::AlignRight | Qt::AlignVCenter,
               QString::number(v));
  }
  for (double px = study_.min_px; px <= study_.max_px * 1.0001; px *= 10.0) {
    const QPointF x = at(box, px, 0.0);
    p.drawText(QRectF(x.x() - 40, box.bottom() + 2, 80, 20), Qt::AlignCenter, QString::number(px));
  }
  p.drawText(QRectF(box.left(), box.bottom() + 20, box.width(), 20), Qt::AlignCenter,
             tr("error shown (px, log scale)"));
  p.save();
  p.translate(12, box.center().y());
  p.rotate(-90);
  p.drawText(QRectF(-box.height() / 2, -10, box.height(), 20), Qt::AlignCenter,
             tr("proportion correct"));
  p.restore();
}

void PsychometricPlot::paint_condition(QPainter& p, const QRectF& box, size_t c) const {
  const std::string& name = study_.conditions[c].name;
  const QColor colour = to_qcolor(policy_colour(int(c)));
  constexpr int kBins = 8;
  std::vector<int> count(kBins), right(kBins);
  const double span = std::log(study_.max_px / study_.min_px);
  for (const TrialRow& r : rows_) {
    if (r.condition != name || r.late) continue;
    const double u = std::log(std::max(r.measured_px, study_.min_px) / study_.min_px) / span;
    const int b = std::clamp(int(u * kBins), 0, kBins - 1);
    ++count[size_t(b)], right[size_t(b)] += r.correct;
  }
  // Each condition's dots a little to the side of the others' at the same bin.
  const double shift = (double(c) - 0.5 * double(study_.conditions.size() - 1)) * 10.0;
  p.setPen(QPen(palette().base().color(), 1.5));
  p.setBrush(colour);
  for (int b = 0; b < kBins; ++b) {
    if (!count[size_t(b)]) continue;
    const double px = study_.min_px * std::exp((b + 0.5) / kBins * span);
    const double radius = 3.0 + 2.0 * std::sqrt(double(count[size_t(b)]));
    p.drawEllipse(at(box, px, double(right[size_t(b)]) / count[size_t(b)]) + QPointF(shift, 0),
                  radius, radius);
  }
  const auto fit = std::find_if(fits_.begin(), fits_.end(),
                                [&](const ThresholdResult& r) { return r.condition == name; });
  if (fit == fits_.end()) return;
  const PsychometricFunction f{fit->threshold_px, study_.assumed_slope, study_.assumed_lapse};
  QPainterPath curve;
  for (int i = 0; i <= 100; ++i) {
    const double px = study_.min_px * std::exp(i / 100.0 * span);
    i == 0 ? curve.moveTo(at(box, px, f.correct(px))) : curve.lineTo(at(box, px, f.correct(px)));
  }
  p.setBrush(Qt::NoBrush);
  p.setPen(QPen(colour, 2.5));
  p.drawPath(curve);
  p.setPen(QPen(colour, 1.5, Qt::DashLine));
  p.drawLine(at(box, fit->threshold_px, 0.0), at(box, fit->threshold_px, 0.75));
  p.drawText(
      at(box, study_.min_px, 0.97 - 0.07 * double(c)) + QPointF(8, 0),
      QString::fromStdString(name) + tr(": threshold %1 px").arg(text_of(fit->threshold_px, 2)));
}

QWidget* StudyWindow::make_results_page() {
  auto* page = new QWidget(this);
  auto* layout = new QVBoxLayout(page);
  results_text_ = new QLabel(page);
  results_text_->setWordWrap(true);
  results_table_ = new QTableWidget(0, 6, page);
  results_table_->setHorizontalHeaderLabels({tr("observer"), tr("condition"), tr("trials (late)"),
                                             tr("threshold, 95 % interval (px)"),
                                             tr("the same in arcmin"), tr("correct")});
  results_table_->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
  plot_ = new PsychometricPlot(page);
  auto* save = new QPushButton(tr("Save the trials as CSV..."), page);
  connect(save, &QPushButton::clicked, this, &StudyWindow::save_csv);
  auto* again = new QPushButton(tr("New session"), page);
  connect(again, &QPushButton::clicked, this, [this] { pages_->setCurrentIndex(0); });
  use_button_ = new QPushButton(page);
  connect(use_button_, &QPushButton::clicked, this,
          [this] { emit threshold_chosen(smallest_threshold_px_); });
  auto* buttons = new QHBoxLayout;
  buttons->addWidget(save);
  buttons->addWidget(use_button_);
  buttons->addWidget(again);
  buttons->addStretch();
  layout->addWidget(results_text_);
  layout->addWidget(results_table_);
  results_table_->setMaximumHeight(8 * results_table_->fontMetrics().height());
  layout->addWidget(plot_, 1);
  layout->addLayout(buttons);
  return page;
}

std::vector<TrialRow> StudyWindow::rows() const {
  return runner_ ? trial_rows(runner_->session(), choice_.observer, choice_.ppi)
                 : std::vector<TrialRow>();
}

void StudyWindow::show_results() {
  clock_.stop();
  phase_ = Phase::kIdle;
  const std::vector<TrialRow> all = rows();
  show_results_of(choice_.study, all,
                  tr("%1: %2 presentations, %3 late (shown again).")
                      .arg(QString::fromStdString(choice_.study.title))
                      .arg(all.size())
                      .arg(runner_ ? runner_->session().late_trials() : 0));
}

void StudyWindow::fill_results_table(const std::vector<ThresholdResult>& fits) {
  results_table_->setRowCount(int(fits.size()));
  for (size_t i = 0; i < fits.size(); ++i) {
    const ThresholdResult& r = fits[i];
    const QString arcmin = r.threshold_arcmin
                               ? interval_text(*r.threshold_arcmin, *r.low_arcmin, *r.high_arcmin)
                               : QString();
    const QStringList cells = {
        r.observer.empty() ? tr("(class)") : QString::fromStdString(r.observer),
        QString::fromStdString(r.condition),
        QStringLiteral("%1 (%2)").arg(r.trials).arg(r.late),
        interval_text(r.threshold_px, r.low_px, r.high_px) +
            (r.at_bound ? tr(" at the fit's bound") : QString()),
        arcmin,
        text_of(r.proportion_correct * 100.0, 0) + " %"};
    for (int c = 0; c < cells.size(); ++c) {
      results_table_->setItem(int(i), c, new QTableWidgetItem(cells[c]));
    }
  }
}

void StudyWindow::show_results_of(const Study& study, const std::vector<TrialRow>& rows,
                                  const QString& heading) {
  pages_->setCurrentIndex(2);
  std::vector<ThresholdResult> fits;
  const bool answered =
      std::any_of(rows.begin(), rows.end(), [](const TrialRow& r) { return !r.late; });
  if (answered) fits = analyse_rows(rows, analysis_settings(study));
  fill_results_table(fits);
  results_text_->setText(heading +
                         tr(" The threshold is the error seen three times in four; for reuse to "
                            "go unseen, the engine's threshold should sit below it."));
  // The plot: the class's pooled fits when there are several observers, else the one's.
  const bool has_class = std::any_of(fits.begin(), fits.end(),
                                     [](const ThresholdResult& r) { return r.observer.empty(); });
  std::vector<ThresholdResult> plotted;
  for (const ThresholdResult& r : fits) {
    if (!has_class || r.observer.empty()) plotted.push_back(r);
  }
  plot_->set(study, rows, plotted);
  smallest_threshold_px_ = 0.0;
  for (const ThresholdResult& r : plotted) {
    if (smallest_threshold_px_ == 0.0 || r.threshold_px < smallest_threshold_px_)
      smallest_threshold_px_ = r.threshold_px;
  }
  use_button_->setEnabled(smallest_threshold_px_ > 0.0);
  use_button_->setText(
      tr("Use %1 px as the window's reuse threshold").arg(text_of(smallest_threshold_px_, 2)));
}

std::string StudyWindow::show_class_results(const std::vector<std::string>& csv_paths) {
  std::vector<TrialRow> rows;
  try {
    for (const std::string& path : csv_paths) {
      const std::vector<TrialRow> more = read_trial_csv(path);
      rows.insert(rows.end(), more.begin(), more.end());
    }
  } catch (const std::exception& e) {  // refused: the page shown stays
    return e.what();
  }
  if (rows.empty()) return "the files hold no trials";
  std::set<std::string> observers;
  for (const TrialRow& r : rows) observers.insert(r.observer);
  show_results_of(study_of_rows(rows), rows,
                  tr("%1 files, %2 observers, %3 presentations of %4.")
                      .arg(csv_paths.size())
                      .arg(observers.size())
                      .arg(rows.size())
                      .arg(QString::fromStdString(rows.front().study)));
  return "";
}

void StudyWindow::open_class_csvs() {
  const QStringList paths = QFileDialog::getOpenFileNames(
      this, tr("Class results: the students' trial files"), QString(), tr("CSV (*.csv)"));
  if (paths.isEmpty()) return;
  std::vector<std::string> list;
  for (const QString& p : paths) list.push_back(p.toStdString());
  const std::string problem = show_class_results(list);
  if (!problem.empty()) setup_status_->setText(QString::fromStdString(problem));
}

std::string StudyWindow::write_csv(const std::string& path, bool replace) const {
  try {
    write_trial_csv(path, rows(), replace ? Overwrite::kReplace : Overwrite::kRefuse);
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

void StudyWindow::save_csv() {
  // The dialog asks before an existing file is replaced.
  const QString path = QFileDialog::getSaveFileName(
      this, tr("Save trials"), QString::fromStdString(choice_.observer + ".csv"),
      tr("CSV (*.csv)"));
  if (path.isEmpty()) return;
  const std::string error = write_csv(path.toStdString(), true);
  results_text_->setText(error.empty() ? tr("Wrote %1.").arg(path) : QString::fromStdString(error));
}

}  // namespace oflab

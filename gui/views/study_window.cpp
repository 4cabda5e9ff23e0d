#include "views/study_window.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QKeyEvent>
#include <QLabel>
#include <QLineEdit>
#include <QPainter>
#include <QPainterPath>
#include <QPushButton>
#include <QScreen>
#include <QSlider>
#include <QSpinBox>
#include <QStackedWidget>
#include <QTableWidget>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>
#include <set>

#include "adapters/frame_images.h"
#include "adapters/paint_helpers.h"
#include "display/palette.h"
#include "formats/atomic_file.h"
#include "study/adaptive_methods.h"

namespace oflab {
namespace {

constexpr double kCardWidthMm = 85.60;  // ISO/IEC 7810 ID-1, a credit card's width
constexpr int kGapMs = 500;             // mid grey between the two clips
const QColor kGrey(128, 128, 128);

QString text_of(double v, int decimals) { return QString::number(v, 'f', decimals); }

// A value and its interval: "0.84 (0.61-1.20)".
QString interval_text(double t, double low, double high) {
  return QStringLiteral("%1 (%2-%3)").arg(text_of(t, 2), text_of(low, 2), text_of(high, 2));
}

}  // namespace

// The clip's frame at one clip pixel to one screen pixel, centred on the mid grey, with the
// text under it.
class StudyCanvas : public QWidget {
 public:
  explicit StudyCanvas(QWidget* parent) : QWidget(parent) {
    setMinimumSize(kClipWidth, kClipHeight);
    setAutoFillBackground(false);
  }
  void show_frame(const Image* frame) {
    frame_ = frame;
    repaint();  // drawn now: the pacer's clock reads the time after it
  }

 protected:
  void paintEvent(QPaintEvent*) override {
    QPainter p(this);
    p.fillRect(rect(), kGrey);
    if (!frame_) return;
    const QPoint at((width() - frame_->width()) / 2, (height() - frame_->height()) / 2);
    p.drawImage(at, image_view(*frame_));
  }

 private:
  const Image* frame_ = nullptr;
};

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

StudyWindow::StudyWindow(QWidget* parent) : QWidget(parent, Qt::Window) {
  setWindowTitle(tr("oflab: how much error can you see?"));
  pages_ = new QStackedWidget(this);
  pages_->addWidget(make_setup_page());
  pages_->addWidget(make_trial_page());
  pages_->addWidget(make_results_page());
  auto* layout = new QVBoxLayout(this);
  layout->addWidget(pages_);
  clock_.setTimerType(Qt::PreciseTimer);
  clock_.setInterval(1);
  connect(&clock_, &QTimer::timeout, this, [this] { tick(); });
  for (const std::string& name : shipped_study_names()) {
    studies_.push_back(find_or_read_study(name));
    study_box_->addItem(QString::fromStdString(name));
  }
  connect(study_box_, qOverload<int>(&QComboBox::currentIndexChanged), this,
          &StudyWindow::study_chosen);
  if (!studies_.empty()) study_chosen(0);
}

StudyWindow::~StudyWindow() = default;

QWidget* StudyWindow::make_setup_page() {
  auto* page = new QWidget(this);
  auto* form = new QFormLayout(page);
  study_box_ = new QComboBox(page);
  auto* open = new QPushButton(tr("Open study file..."), page);
  connect(open, &QPushButton::clicked, this, &StudyWindow::open_study_file);
  auto* row = new QHBoxLayout;
  row->addWidget(study_box_, 1);
  row->addWidget(open);
  form->addRow(tr("Study"), row);
  study_text_ = new QLabel(page);
  study_text_->setWordWrap(true);
  form->addRow(QString(), study_text_);
  method_box_ = new QComboBox(page);
  for (const AdaptiveMethodKind& m : adaptive_methods()) method_box_->addItem(m.name);
  form->addRow(tr("Method"), method_box_);
  observer_edit_ = new QLineEdit(tr("observer"), page);
  form->addRow(tr("Your name or code"), observer_edit_);
  ppi_box_ = new QDoubleSpinBox(page);
  ppi_box_->setRange(study_limits::kPpi.minimum, study_limits::kPpi.maximum);
  ppi_box_->setDecimals(1);
  ppi_box_->setValue(screen() ? screen()->physicalDotsPerInch() : 96.0);
  form->addRow(tr("Screen pixels per inch"), ppi_box_);
  form->addRow(QString(), make_card_measure());
  seed_box_ = new QSpinBox(page);
  seed_box_->setRange(0, 1 << 30);
  form->addRow(tr("Seed"), seed_box_);
  auto* start_button = new QPushButton(tr("Start"), page);
  connect(start_button, &QPushButton::clicked, this, &StudyWindow::start);
  auto* class_button = new QPushButton(tr("Class results from trial files..."), page);
  connect(class_button, &QPushButton::clicked, this, &StudyWindow::open_class_csvs);
  auto* start_row = new QHBoxLayout;
  start_row->addWidget(start_button, 1);
  start_row->addWidget(class_button);
  form->addRow(QString(), start_row);
  setup_status_ = new QLabel(page);
  setup_status_->setWordWrap(true);
  form->addRow(QString(), setup_status_);
  return page;
}

// A bar to drag to a credit card's width held against the screen: the pixels per inch from it.
QWidget* StudyWindow::make_card_measure() {
  auto* box = new QWidget(this);
  auto* layout = new QVBoxLayout(box);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->addWidget(new QLabel(tr("Or hold a credit card to the screen and drag until the "
                                  "bar is as wide as the card:"),
                               box));
  auto* bar = new QLabel(box);
  bar->setFixedHeight(24);
  bar->setStyleSheet(QStringLiteral("background: #3070c0"));
  auto* slider = new QSlider(Qt::Horizontal, box);
  slider->setRange(100, 1200);
  slider->setValue(int(std::lround(ppi_box_->value() * kCardWidthMm / 25.4)));
  bar->setFixedWidth(slider->value());
  connect(slider, &QSlider::valueChanged, this, [this, bar](int px) {
    bar->setFixedWidth(px);
    ppi_box_->setValue(px / (kCardWidthMm / 25.4));
  });
  layout->addWidget(bar);
  layout->addWidget(slider);
  return box;
}

QWidget* StudyWindow::make_trial_page() {
  auto* page = new QWidget(this);
  auto* layout = new QVBoxLayout(page);
  trial_text_ = new QLabel(page);
  trial_text_->setAlignment(Qt::AlignCenter);
  canvas_ = new StudyCanvas(page);
  layout->addWidget(trial_text_);
  layout->addWidget(canvas_, 1);
  auto* buttons = new QHBoxLayout;
  first_button_ = new QPushButton(tr("1: the first clip was distorted"), page);
  second_button_ = new QPushButton(tr("2: the second clip was distorted"), page);
  connect(first_button_, &QPushButton::clicked, this, [this] { answer(1); });
  connect(second_button_, &QPushButton::clicked, this, [this] { answer(2); });
  auto* stop = new QPushButton(tr("Stop and show the results"), page);
  connect(stop, &QPushButton::clicked, this, &StudyWindow::show_results);
  buttons->addWidget(first_button_);
  buttons->addWidget(second_button_);
  buttons->addStretch();
  buttons->addWidget(stop);
  layout->addLayout(buttons);
  return page;
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

void StudyWindow::select_study(const Study& study) {
  for (size_t i = 0; i < studies_.size(); ++i) {
    if (studies_[i].name == study.name) studies_.erase(studies_.begin() + long(i));
  }
  studies_.push_back(study);
  study_box_->blockSignals(true);
  study_box_->clear();
  for (const Study& s : studies_) study_box_->addItem(QString::fromStdString(s.name));
  study_box_->blockSignals(false);
  study_box_->setCurrentIndex(int(studies_.size()) - 1);
  study_chosen(int(studies_.size()) - 1);
}

void StudyWindow::study_chosen(int index) {
  if (index < 0 || index >= int(studies_.size())) return;
  const Study& s = studies_[size_t(index)];
  study_text_->setText(
      QString::fromStdString(s.title + ": " + s.description) +
      tr(" (%1 conditions, %2 trials each)").arg(s.conditions.size()).arg(s.trials));
  method_box_->setCurrentText(QString::fromStdString(s.method));
  seed_box_->setValue(int(std::min<std::uint64_t>(s.seed, std::uint64_t(1) << 30)));
}

void StudyWindow::open_study_file() {
  const QString path =
      QFileDialog::getOpenFileName(this, tr("Open study"), QString(), tr("Study files (*.json)"));
  if (path.isEmpty()) return;
  try {
    select_study(read_study_file(path.toStdString()));
    setup_status_->clear();
  } catch (const std::exception& e) {  // refused: the study chosen before stays
    setup_status_->setText(QString::fromStdString(e.what()));
  }
}

void StudyWindow::set_fields(const std::string& method, const std::string& observer, double ppi,
                             std::uint64_t seed) {
  method_box_->setCurrentText(QString::fromStdString(method));
  if (!observer.empty()) observer_edit_->setText(QString::fromStdString(observer));
  ppi_box_->setValue(ppi);
  seed_box_->setValue(int(seed));
}

std::string StudyWindow::read_choice(StudyChoice* choice) const {
  const int index = study_box_->currentIndex();
  if (index < 0 || index >= int(studies_.size())) return "no study is chosen";
  const std::string observer = observer_edit_->text().trimmed().toStdString();
  if (observer.empty() || observer.find_first_of(",\n\r") != std::string::npos) {
    return "your name or code: some text without commas";
  }
  choice->study = studies_[size_t(index)];
  choice->method = method_box_->currentText().toStdString();
  choice->observer = observer;
  choice->ppi = ppi_box_->value();
  choice->seed = std::uint64_t(seed_box_->value());
  return "";
}

void StudyWindow::start() {
  const std::string problem = read_choice(&choice_);
  if (!problem.empty()) {
    setup_status_->setText(QString::fromStdString(problem));
    return;
  }
  setup_status_->setText(
      tr("Measuring the errors the engine shows (about a second per "
         "condition)..."));
  repaint();
  runner_ = std::make_unique<TrialRunner>(choice_.study, choice_.method, choice_.seed);
  setup_status_->clear();
  pages_->setCurrentIndex(1);
  begin_rate_check();
}

// A second of frames before the first trial, the first request's exact clip (the motion
// without error): the study needs every frame on time.
void StudyWindow::begin_rate_check() {
  trial_text_->setText(tr("Checking that this display shows %1 frames per second: the "
                          "motion without error...")
                           .arg(kClipFrameRate));
  first_button_->setEnabled(false);
  second_button_->setEnabled(false);
  late_frames_ = 0;
  runner_->clips();  // made before the clock starts
  play_phase(Phase::kRateCheck);
}

const std::vector<Image>& StudyWindow::exact_clip() {
  const TrialClips& clips = runner_->clips();
  return runner_->request().distorted_first ? clips.second : clips.first;
}

void StudyWindow::play_phase(Phase phase) {
  phase_ = phase;
  frame_ = 0;
  elapsed_.start();
  pacer_.start(0, phase == Phase::kGap ? 1000.0 / kGapMs : double(kClipFrameRate));
  if (phase == Phase::kFirst) canvas_->show_frame(&runner_->clips().first[0]);
  if (phase == Phase::kSecond) canvas_->show_frame(&runner_->clips().second[0]);
  if (phase == Phase::kRateCheck) canvas_->show_frame(&exact_clip()[0]);
  if (phase == Phase::kGap) canvas_->show_frame(nullptr);
  clock_.start();
}

void StudyWindow::tick() {
  const int due = pacer_.frames_due(elapsed_.elapsed());
  if (due == 0) return;
  const int length = phase_ == Phase::kGap ? 1 : int(runner_->clips().first.size());
  if (due > 1 && phase_ != Phase::kGap) {  // frames skipped (those past the clip's end not counted)
    late_ = true;
    late_frames_ += std::min(frame_ + due, length) - frame_ - 1;
  }
  frame_ += due;
  if (frame_ >= length) return clip_ended();
  const std::vector<Image>& clip = phase_ == Phase::kRateCheck ? exact_clip()
                                   : phase_ == Phase::kFirst   ? runner_->clips().first
                                                               : runner_->clips().second;
  canvas_->show_frame(&clip[size_t(frame_)]);
}

void StudyWindow::clip_ended() {
  clock_.stop();
  switch (phase_) {
    case Phase::kRateCheck:
      if (late_frames_ > 0) {
        pages_->setCurrentIndex(0);
        setup_status_->setText(tr("This display drew %1 of %2 frames late at %3 frames per "
                                  "second; a trial must show every frame on time. Close other "
                                  "programs, or use another display, and start again.")
                                   .arg(late_frames_)
                                   .arg(int(exact_clip().size()))
                                   .arg(kClipFrameRate));
        return;
      }
      return next_trial();
    case Phase::kFirst:
      return play_phase(Phase::kGap);
    case Phase::kGap:
      return play_phase(Phase::kSecond);
    case Phase::kSecond:
      phase_ = Phase::kAnswer;
      canvas_->show_frame(nullptr);
      update_trial_text();
      first_button_->setEnabled(true);
      second_button_->setEnabled(true);
      return;
    default:
      return;
  }
}

void StudyWindow::next_trial() {
  if (runner_->finished()) return show_results();
  late_ = false;
  first_button_->setEnabled(false);
  second_button_->setEnabled(false);
  update_trial_text();
  runner_->clips();  // made before the clock starts
  play_phase(Phase::kFirst);
}

void StudyWindow::update_trial_text() {
  const StudySession& s = runner_->session();
  const StudyCondition& c = s.study().conditions[size_t(s.request().condition)];
  const int total = s.study().trials * int(s.study().conditions.size());
  int answered = 0;
  for (const StudyTrial& t : s.trials()) answered += !t.late;
  const QString where =
      tr("Trial %1 of %2 (%3)").arg(answered + 1).arg(total).arg(QString::fromStdString(c.name));
  trial_text_->setText(phase_ == Phase::kAnswer
                           ? where + tr(": which clip was distorted? Press 1 or 2.")
                           : where + tr(": watch both clips."));
}

void StudyWindow::answer(int chosen) {
  if (phase_ != Phase::kAnswer || !runner_) return;
  runner_->answer(chosen, late_);
  next_trial();
}

void StudyWindow::keyPressEvent(QKeyEvent* event) {
  if (event->key() == Qt::Key_1) return answer(1);
  if (event->key() == Qt::Key_2) return answer(2);
  QWidget::keyPressEvent(event);
}

void StudyWindow::hideEvent(QHideEvent* event) {
  if (phase_ != Phase::kIdle) {
    clock_.stop();
    phase_ = Phase::kIdle;
    pages_->setCurrentIndex(0);
    setup_status_->setText(
        tr("The study window was closed during a trial: Start begins a new "
           "session."));
  }
  QWidget::hideEvent(event);
}

std::string StudyWindow::run_simulated(SimulatedObserver& observer) {
  const std::string problem = read_choice(&choice_);
  if (!problem.empty()) return problem;
  runner_ = std::make_unique<TrialRunner>(choice_.study, choice_.method, choice_.seed);
  pages_->setCurrentIndex(1);
  while (!runner_->finished()) {
    const TrialClips& clips = runner_->clips();
    canvas_->show_frame(&clips.first.back());
    canvas_->show_frame(&clips.second.back());
    const SimulatedObserver::Answer a = observer.answer(clips.measured_px);
    phase_ = Phase::kAnswer;
    late_ = a.late;
    answer(runner_->chosen_for(a.correct));
  }
  return "";
}

int StudyWindow::first_clip_frame() const {
  const bool first_trial = runner_ && runner_->session().trials().empty();
  return first_trial && phase_ == Phase::kFirst ? frame_ : -1;
}

std::string StudyWindow::setup_status() const { return setup_status_->text().toStdString(); }

const StudySession* StudyWindow::session() const { return runner_ ? &runner_->session() : nullptr; }

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

#include "views/study_window.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QKeyEvent>
#include <QLabel>
#include <QLineEdit>
#include <QPainter>
#include <QPushButton>
#include <QScreen>
#include <QSlider>
#include <QSpinBox>
#include <QStackedWidget>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>

#include "adapters/frame_images.h"
#include "study/adaptive_methods.h"

namespace oflab {
namespace {

constexpr double kCardWidthMm = 85.60;  // ISO/IEC 7810 ID-1, a credit card's width
constexpr int kGapMs = 500;             // mid grey between the two clips
const QColor kGrey(128, 128, 128);

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
  const int answered = s.answered_trials();
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

}  // namespace oflab

#include "app/main_window.h"

#include <QAbstractSpinBox>
#include <QAction>
#include <QApplication>
#include <QComboBox>
#include <QDockWidget>
#include <QFileDialog>
#include <QKeyEvent>
#include <QLabel>
#include <QLineEdit>
#include <QMenuBar>
#include <QScrollArea>
#include <QSlider>
#include <QSplitter>
#include <QStackedWidget>
#include <QStatusBar>
#include <QTabWidget>
#include <QTimer>
#include <QToolBar>
#include <QVBoxLayout>
#include <algorithm>

#include "app/app_theme.h"
#include "app/screenshot.h"
#include "app/view_table.h"
#include "formats/datasets.h"
#include "models/animation_model.h"
#include "models/scene_model.h"
#include "models/window_model.h"
#include "player/animation_sources.h"
#include "state/window_state_file.h"
#include "views/scene_controls.h"
#include "views/study_window.h"
#include "views/view_page.h"

namespace oflab {

MainWindow::MainWindow(QWidget* parent) : QMainWindow(parent) {
  setWindowTitle(tr("oflab - Optic Flow Lab"));
  model_ = new WindowModel(view_table_names(), this);
  SceneModel* scene = model_->scene();
  motion_timer_ = new QTimer(this);
  motion_timer_->setTimerType(Qt::PreciseTimer);
  motion_timer_->setInterval(static_cast<int>(1000.0 * SceneModel::kSecondsPerFrame));
  // Frames follow the wall clock: a late tick advances by the frames due (dropping some),
  // so the motion keeps real speed when drawing is slower than the rate.
  connect(motion_timer_, &QTimer::timeout, this, [this] {
    const int due = pacer_.frames_due(play_clock_.elapsed());
    if (due <= 0) return;
    model_->scene()->advance(due);
  });

  auto* central = new QWidget(this);
  auto* layout = new QVBoxLayout(central);
  layout->setContentsMargins(4, 4, 4, 4);
  layout->addWidget(create_banners());
  stack_ = new QStackedWidget(central);
  tabs_ = new QTabWidget(stack_);
  tabs_->setObjectName(QStringLiteral("view_tabs"));
  stack_->addWidget(tabs_);
  layout->addWidget(stack_, 1);
  setCentralWidget(central);

  for (const ViewEntry& entry : view_table()) add_view(entry);
  connect(model_, &WindowModel::input_rejected, this, &MainWindow::show_message);

  controls_ = new SceneControls(scene);
  connect(controls_, &SceneControls::refused, model_, &WindowModel::reject);
  auto* scroll = new QScrollArea;
  scroll->setWidget(controls_);
  scroll->setWidgetResizable(true);
  scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
  scene_dock_ = new QDockWidget(tr("Scene"), this);
  scene_dock_->setObjectName(QStringLiteral("scene_dock"));
  scene_dock_->setWidget(scroll);
  scene_dock_->setFeatures(QDockWidget::DockWidgetMovable | QDockWidget::DockWidgetFloatable |
                           QDockWidget::DockWidgetClosable);
  addDockWidget(Qt::LeftDockWidgetArea, scene_dock_);
  fit_scene_panel();
  connect(tabs_, &QTabWidget::currentChanged, this, [this] {
    model_->set_view(current_view_name().toStdString());
    update_scene_panel();
  });
  // An accepted source or settings change clears a refusal of an earlier one.
  connect(model_->animation(), &AnimationModel::source_changed, this, [this] {
    clear_message();
    update_scene_panel();
    update_source_status();
  });

  create_actions();
  create_menus();
  create_play_bar();
  connect(scene, &SceneModel::scene_changed, this, [this] {
    clear_message();
    update_frame_label();
  });
  connect(model_, &WindowModel::view_changed, this, &MainWindow::show_model_view);
  connect(model_, &WindowModel::presentation_changed, this, &MainWindow::show_presentation);
  connect(model_, &WindowModel::play_changed, this, &MainWindow::show_play);
  connect(model_, &WindowModel::lesson_changed, this, &MainWindow::show_lesson);
  connect(model_, &WindowModel::layout_changed, this, &MainWindow::show_layout);
  connect(model_, &WindowModel::scene_panel_changed, this,
          [this] { scene_dock_->setVisible(model_->scene_panel()); });
  // Closed with its title bar's button (not hidden by a minimised window): the model hears.
  connect(scene_dock_->toggleViewAction(), &QAction::toggled, model_,
          &WindowModel::set_scene_panel);
  apply_app_theme(view_theme(false));
  QApplication::instance()->installEventFilter(this);
  source_status_ = new QLabel(this);
  source_status_->setObjectName(QStringLiteral("source_status"));
  statusBar()->addPermanentWidget(source_status_);
  update_source_status();
  resize(1280, 800);
}

QWidget* MainWindow::create_banners() {
  auto* box = new QWidget(this);
  auto* layout = new QVBoxLayout(box);
  layout->setContentsMargins(0, 0, 0, 0);
  caption_banner_ = new QLabel(box);
  caption_banner_->setObjectName(QStringLiteral("caption_banner"));
  caption_banner_->setWordWrap(true);
  caption_banner_->hide();
  message_banner_ = new QLabel(box);
  message_banner_->setObjectName(QStringLiteral("message_banner"));
  message_banner_->setWordWrap(true);
  message_banner_->hide();
  style_banners();
  layout->addWidget(caption_banner_);
  layout->addWidget(message_banner_);
  return box;
}

void MainWindow::update_source_status() {
  source_status_->setText(
      tr("Animation plays: %1")
          .arg(QString::fromStdString(describe_source(model_->animation()->source()))));
}

void MainWindow::update_scene_panel() {
  const ViewPage* page = current_view();
  controls_->set_note(page ? page->scene_panel_note() : QString());
}

void MainWindow::create_actions() {
  play_action_ = new QAction(tr("Play motion"), this);
  play_action_->setCheckable(true);
  play_action_->setShortcut(Qt::Key_Space);
  play_action_->setToolTip(tr("Play or pause the scene's motion (Space)"));
  connect(play_action_, &QAction::toggled, model_, &WindowModel::set_playing);
  step_action_ = new QAction(tr("Step"), this);
  step_action_->setShortcut(Qt::Key_Right);
  step_action_->setToolTip(tr("One frame forward (Right arrow)"));
  connect(step_action_, &QAction::triggered, this, [this] { model_->scene()->advance(1); });
  back_action_ = new QAction(tr("Back"), this);
  back_action_->setShortcut(Qt::Key_Left);
  back_action_->setToolTip(tr("One frame back (Left arrow)"));
  connect(back_action_, &QAction::triggered, this,
          [this] { model_->scene()->set_frame(std::max(0, model_->scene()->frame() - 1)); });
  end_action_ = new QAction(tr("Last frame"), this);
  end_action_->setShortcut(Qt::Key_End);
  end_action_->setToolTip(tr("The last frame of the loop (End)"));
  connect(end_action_, &QAction::triggered, this,
          [this] { model_->scene()->set_frame(model_->scene()->loop_frames() - 1); });
  reset_action_ = new QAction(tr("First frame"), this);
  reset_action_->setShortcut(Qt::Key_Home);
  reset_action_->setToolTip(tr("Back to frame 0 (Home)"));
  connect(reset_action_, &QAction::triggered, this, [this] { model_->scene()->set_frame(0); });
  stop_action_ = new QAction(tr("Stop"), this);
  stop_action_->setShortcut(Qt::Key_Escape);
  stop_action_->setToolTip(tr("Stop playing frames or a lesson's steps (Escape)"));
  connect(stop_action_, &QAction::triggered, this, &MainWindow::cancel_long_work);
  presentation_action_ = new QAction(tr("Presentation mode"), this);
  presentation_action_->setCheckable(true);
  presentation_action_->setShortcut(Qt::Key_F11);
  presentation_action_->setToolTip(
      tr("Light backgrounds, large text and thick lines for a projector (F11)"));
  connect(presentation_action_, &QAction::toggled, model_, &WindowModel::set_presentation);
  layout_action_ = new QAction(tr("Cause and effect"), this);
  layout_action_->setCheckable(true);
  layout_action_->setShortcut(Qt::Key_F8);
  layout_action_->setToolTip(
      tr("The world view (the cause) beside the flow view (the effect), instead of the tabs "
         "(F8)"));
  connect(layout_action_, &QAction::toggled, model_, &WindowModel::set_cause_and_effect);
}

void MainWindow::create_menus() {
  QMenu* file = menuBar()->addMenu(tr("&File"));
  connect(file->addAction(tr("Load texture...")), &QAction::triggered, this,
          &MainWindow::load_texture);
  connect(file->addAction(tr("Open script...")), &QAction::triggered, this, [this] {
    const QString path = QFileDialog::getOpenFileName(this, tr("Open motion script"), QString(),
                                                      tr("Motion scripts (*.json)"));
    if (!path.isEmpty()) load_script(path);
  });
  QMenu* shipped = file->addMenu(tr("Shipped scripts"));
  for (const std::string& name : shipped_script_names()) {
    const QString q = QString::fromStdString(name);
    connect(shipped->addAction(q), &QAction::triggered, this, [this, q] { load_script(q); });
  }
  connect(file->addAction(tr("Save window screenshot...")), &QAction::triggered, this,
          &MainWindow::save_screenshot);
  create_export_menu(file);
  file->addSeparator();
  QAction* quit = file->addAction(tr("Quit"));
  quit->setShortcut(QKeySequence::Quit);
  connect(quit, &QAction::triggered, this, &QWidget::close);
  QMenu* view = menuBar()->addMenu(tr("&View"));
  view->addAction(presentation_action_);
  view->addAction(layout_action_);
  QAction* panel = scene_dock_->toggleViewAction();
  panel->setText(tr("Scene panel"));
  panel->setShortcut(Qt::Key_F9);
  panel->setToolTip(tr("Show or hide the scene panel (F9)"));
  view->addAction(panel);
  for (QAction* a :
       {play_action_, step_action_, back_action_, reset_action_, end_action_, stop_action_}) {
    view->addAction(a);
  }
  create_view_shortcuts(view);
  QMenu* lesson_menu = menuBar()->addMenu(tr("&Lessons"));
  try {
    for (const Lesson& lesson : lessons()) {
      const std::string name = lesson.name;
      connect(lesson_menu->addAction(QString::fromStdString(lesson.title)), &QAction::triggered,
              this, [this, name] { apply_lesson(*find_lesson(name)); });
    }
  } catch (const SessionError& e) {  // a broken lesson file: the window opens without lessons
    show_message(QString::fromStdString(e.what()));
  }
  lesson_menu->addSeparator();
  QAction* next = lesson_menu->addAction(tr("Next step"));
  next->setShortcut(Qt::Key_PageDown);
  connect(next, &QAction::triggered, this, [this] { step_lesson(+1); });
  QAction* previous = lesson_menu->addAction(tr("Previous step"));
  previous->setShortcut(Qt::Key_PageUp);
  connect(previous, &QAction::triggered, this, [this] { step_lesson(-1); });
  QMenu* study_menu = menuBar()->addMenu(tr("&Study"));
  connect(study_menu->addAction(tr("How much error can you see? (threshold study)...")),
          &QAction::triggered, this, [this] { open_study_window(); });
}

StudyWindow* MainWindow::open_study_window() {
  if (!study_window_) {
    study_window_ = new StudyWindow(this);
    connect(study_window_, &StudyWindow::threshold_chosen, this, [this](double px) {
      WindowState state = model_->state();
      state.settings.thresholds = {px, px, px, px};
      QString error;
      if (!model_->apply(state, &error)) show_message(error);
    });
    study_window_->resize(std::max(900, width() * 3 / 4), std::max(720, height() * 3 / 4));
  }
  study_window_->show();
  study_window_->raise();
  study_window_->activateWindow();
  return study_window_;
}

void MainWindow::create_play_bar() {
  QToolBar* bar = addToolBar(tr("Play"));
  bar->setObjectName(QStringLiteral("play_bar"));
  for (QAction* a : {reset_action_, back_action_, play_action_, step_action_, end_action_}) {
    bar->addAction(a);
  }
  frame_label_ = new QLabel(bar);
  bar->addWidget(frame_label_);
  add_scrub_controls(bar);
  bar->addSeparator();
  bar->addAction(presentation_action_);
  update_frame_label();
}

void MainWindow::add_scrub_controls(QToolBar* bar) {
  scrub_ = new QSlider(Qt::Horizontal, bar);
  scrub_->setObjectName(QStringLiteral("scrub_slider"));
  scrub_->setMinimumWidth(120);
  scrub_->setToolTip(tr("Scrub through the frames of the motion"));
  // Fusion draws the groove a shade off the window's colour, which vanishes on the dark look:
  // a mid-grey groove shows on both looks, the played part in the highlight blue.
  scrub_->setStyleSheet(QStringLiteral(
      "QSlider::groove:horizontal { height: 6px; background: rgb(128, 132, 140);"
      " border-radius: 3px; }"
      "QSlider::sub-page:horizontal { background: rgb(0, 114, 178); border-radius: 3px; }"
      "QSlider::handle:horizontal { background: rgb(235, 235, 235); border: 1px solid"
      " rgb(90, 90, 90); width: 14px; margin: -5px 0; border-radius: 7px; }"));
  bar->addWidget(scrub_);
  connect(scrub_, &QSlider::valueChanged, this,
          [this](int frame) { model_->scene()->set_frame(frame); });
  speed_box_ = new QComboBox(bar);
  speed_box_->setObjectName(QStringLiteral("speed_box"));
  speed_box_->setToolTip(tr("Playback rate, frames per second"));
  for (int fps : {5, 10, 15, 30, 60}) speed_box_->addItem(tr("%1 fps").arg(fps), fps);
  speed_box_->setCurrentIndex(3);
  bar->addWidget(speed_box_);
  connect(speed_box_, QOverload<int>::of(&QComboBox::activated), this,
          [this] { model_->set_play_rate(speed_box_->currentData().toInt()); });
}

void MainWindow::update_frame_label() {
  const SceneModel* scene = model_->scene();
  frame_label_->setText(
      tr("  frame %1 (t = %2 s)").arg(scene->frame()).arg(scene->time(), 0, 'f', 2));
  if (!scrub_) return;
  const QSignalBlocker block(scrub_);
  scrub_->setRange(0, scene->loop_frames() - 1);
  scrub_->setValue(scene->frame());
}

void MainWindow::add_view(const ViewEntry& entry) {
  ViewPage* page = entry.make(model_);
  page->setFocusPolicy(Qt::StrongFocus);  // clicking a view takes the focus from a field
  views_.push_back({QString::fromStdString(entry.name), page});
  tabs_->addTab(page, tr(entry.title.c_str()));
  page->set_theme(theme());
}

ViewPage* MainWindow::view(const QString& name) const {
  for (const Tab& tab : views_) {
    if (tab.name == name) return tab.page;
  }
  return nullptr;
}

QStringList MainWindow::view_names() const {
  QStringList names;
  for (const Tab& tab : views_) names << tab.name;
  return names;
}

QString MainWindow::current_view_name() const {
  for (const Tab& tab : views_) {
    if (tab.page == tabs_->currentWidget()) return tab.name;
  }
  return QString();
}

bool MainWindow::show_view(const QString& name) {
  return view(name) && model_->set_view(name.toStdString());
}

void MainWindow::show_model_view() {
  ViewPage* page = view(QString::fromStdString(model_->view()));
  if (page && page != tabs_->currentWidget()) tabs_->setCurrentWidget(page);
}

ViewPage* MainWindow::current_view() const {
  return static_cast<ViewPage*>(tabs_->currentWidget());
}

void MainWindow::apply_lesson(const Lesson& lesson) {
  QString error;
  WindowState state = lesson.state;
  state.presentation = model_->presentation();  // the teacher's look stays as it is
  if (!model_->apply(state, &error)) {
    show_message(tr("%1.json: %2").arg(QString::fromStdString(lesson.name), error));
    return;
  }
  statusBar()->showMessage(tr("Lesson: %1").arg(QString::fromStdString(lesson.title)));
}

QString MainWindow::caption() const {
  return caption_banner_->isVisible() ? caption_banner_->text() : QString();
}

bool MainWindow::perform_lesson_step(const Lesson& lesson, int step) {
  cancelled_ = false;
  const std::string problem = oflab::perform_lesson_step(*this, lesson, step);
  if (!problem.empty()) show_message(QString::fromStdString(problem));
  return problem.empty();
}

bool MainWindow::go_to_lesson_step(const Lesson& lesson, int step) {
  cancelled_ = false;
  const std::string problem = oflab::go_to_lesson_step(*this, lesson, step, !external_clock_);
  if (!problem.empty()) show_message(QString::fromStdString(problem));
  return problem.empty();
}

WindowState MainWindow::stage_state() const { return model_->state(); }

std::string MainWindow::stage_apply(const WindowState& state) {
  QString error;
  return model_->apply(state, &error) ? std::string() : error.toStdString();
}

void MainWindow::stage_stop() { model_->set_playing(false); }

void MainWindow::stage_seek(int frame) { model_->scene()->set_frame(frame); }

int MainWindow::stage_loop_frames() const { return model_->scene()->loop_frames(); }

void MainWindow::stage_set_step(int step) { model_->set_lesson_step(step); }

void MainWindow::step_lesson(int delta) {
  const Lesson* lesson = find_lesson(model_->lesson());
  if (!lesson || playing_frames_) return;  // a step still playing: Escape stops it
  const int step = model_->lesson_step() + delta;
  if (step < 0 || step > int(lesson->steps.size())) return;
  if (delta == 1) {
    perform_lesson_step(*lesson, step);
  } else {
    go_to_lesson_step(*lesson, step);
  }
}

void MainWindow::show_lesson() {
  const Lesson* lesson = find_lesson(model_->lesson());
  const int step = model_->lesson_step();
  QString text;
  if (lesson && step == 0) text = QString::fromStdString(lesson->narrative);
  if (lesson && step > 0 && step <= int(lesson->steps.size())) {
    text = tr("Step %1 of %2. %3")
               .arg(step)
               .arg(lesson->steps.size())
               .arg(QString::fromStdString(lesson->steps[size_t(step - 1)].say));
  }
  caption_banner_->setText(text);
  caption_banner_->setVisible(lesson != nullptr);
  if (lesson) statusBar()->showMessage(tr("Lesson: %1").arg(QString::fromStdString(lesson->title)));
}

QString MainWindow::message() const {
  return message_banner_->isVisible() ? message_banner_->text() : QString();
}

void MainWindow::show_message(const QString& text) {
  message_banner_->setText(tr("Not applied: %1. The scene is unchanged.").arg(text));
  message_banner_->show();
  statusBar()->showMessage(message_banner_->text(), 10000);
}

void MainWindow::clear_message() { message_banner_->hide(); }

void MainWindow::show_play() {
  const int rate = model_->play_rate();
  if (speed_box_->findData(rate) < 0) speed_box_->addItem(tr("%1 fps").arg(rate), rate);
  speed_box_->setCurrentIndex(speed_box_->findData(rate));
  motion_timer_->setInterval(1000 / rate);
  const QSignalBlocker block(play_action_);
  play_action_->setChecked(model_->playing());
  if (model_->playing() && !external_clock_) {
    play_clock_.start();
    pacer_.start(0, rate);
    if (!motion_timer_->isActive()) motion_timer_->start();
  } else {
    motion_timer_->stop();
  }
}

void MainWindow::set_external_clock(bool on) {
  external_clock_ = on;
  show_play();
  for (const Tab& tab : views_) tab.page->set_external_clock(on);
  for (ViewPage* page : layout_views_) page->set_external_clock(on);
}

void MainWindow::play_frames(int frames) {
  if (playing_frames_) return;
  playing_frames_ = true;
  struct Done {  // also when the engine throws (report_failure then shows it)
    bool& flag;
    ~Done() { flag = false; }
  } done{playing_frames_};
  for (int i = 0; i < frames && !cancelled_; ++i) {
    model_->scene()->advance(1);
    for (const Tab& tab : views_) tab.page->step_animation();
    for (ViewPage* page : layout_views_) page->step_animation();
    QApplication::processEvents();
  }
}

void MainWindow::cancel_long_work() {
  cancelled_ = true;
  model_->set_playing(false);
  statusBar()->showMessage(tr("Stopped at frame %1 (Escape)").arg(model_->scene()->frame()), 10000);
}

void MainWindow::report_failure(const QString& what) {
  cancelled_ = true;
  model_->set_playing(false);
  message_banner_->setText(tr("Stopped: %1. Choose a smaller scene or camera.").arg(what));
  message_banner_->show();
  statusBar()->showMessage(message_banner_->text(), 10000);
}

void MainWindow::closeEvent(QCloseEvent* event) {
  cancelled_ = true;
  QMainWindow::closeEvent(event);
}

void MainWindow::show_layout() {
  const bool on = model_->cause_and_effect();
  if (on && !cause_effect_) {  // made on first use, from the view table
    cause_effect_ = new QSplitter(Qt::Horizontal, stack_);
    cause_effect_->setObjectName(QStringLiteral("cause_and_effect"));
    for (const char* name : {"world", "flow"}) {
      ViewPage* page = find_view_entry(name)->make(model_);
      page->setFocusPolicy(Qt::StrongFocus);
      page->set_theme(theme());
      page->set_external_clock(external_clock_);
      cause_effect_->addWidget(page);
      layout_views_.push_back(page);
    }
    stack_->addWidget(cause_effect_);
  }
  if (cause_effect_) stack_->setCurrentWidget(on ? static_cast<QWidget*>(cause_effect_) : tabs_);
  const QSignalBlocker block(layout_action_);
  layout_action_->setChecked(on);
}

void MainWindow::create_view_shortcuts(QMenu* menu) {
  // Ctrl+1 .. Ctrl+9 bring the Nth view of the table to the front.
  menu->addSeparator();
  const std::vector<ViewEntry>& table = view_table();
  for (int i = 0; i < int(table.size()) && i < 9; ++i) {
    const QString title = tr(table[size_t(i)].title.c_str());
    const QKeySequence keys(Qt::CTRL + Qt::Key_1 + i);
    QAction* show = menu->addAction(tr("Show %1").arg(title));
    show->setShortcut(keys);
    connect(show, &QAction::triggered, this, [this, i] { tabs_->setCurrentIndex(i); });
    tabs_->setTabToolTip(i, tr("%1 (%2)").arg(title, keys.toString(QKeySequence::NativeText)));
  }
}

bool MainWindow::handle_play_key(QWidget* target, int key) {
  // A field being typed into keeps its keys (the cursor, the space); Enter commits it.
  auto* field = qobject_cast<QLineEdit*>(target);
  if (!field && qobject_cast<QAbstractSpinBox*>(target)) field = target->findChild<QLineEdit*>();
  if (field && field->isModified()) return false;
  QAction* action = nullptr;
  switch (key) {
    case Qt::Key_Space:
      action = play_action_;
      break;
    case Qt::Key_Left:
      action = back_action_;
      break;
    case Qt::Key_Right:
      action = step_action_;
      break;
    case Qt::Key_Home:
      action = reset_action_;
      break;
    case Qt::Key_End:
      action = end_action_;
      break;
    case Qt::Key_Escape:
      action = stop_action_;
      break;
    default:
      return false;
  }
  action->trigger();
  return true;
}

bool MainWindow::eventFilter(QObject* watched, QEvent* event) {
  if (event->type() != QEvent::KeyPress) return QMainWindow::eventFilter(watched, event);
  auto* widget = qobject_cast<QWidget*>(watched);
  const auto* key = static_cast<QKeyEvent*>(event);
  if (!widget || widget->window() != this || (key->modifiers() & ~Qt::KeypadModifier)) {
    return QMainWindow::eventFilter(watched, event);
  }
  const bool in_number_field = qobject_cast<QAbstractSpinBox*>(widget) ||
                               qobject_cast<QAbstractSpinBox*>(widget->parentWidget());
  if (in_number_field && (key->key() == Qt::Key_Return || key->key() == Qt::Key_Enter)) {
    // The field applies the value first; then the view gets the keys back.
    QTimer::singleShot(0, this, [this] {
      if (current_view()) current_view()->setFocus(Qt::OtherFocusReason);
    });
    return QMainWindow::eventFilter(watched, event);
  }
  return handle_play_key(widget, key->key()) || QMainWindow::eventFilter(watched, event);
}

}  // namespace oflab

#include "views/animation_controls.h"

#include <QActionGroup>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QHBoxLayout>
#include <QKeyEvent>
#include <QLabel>
#include <QMenu>
#include <QMouseEvent>
#include <QPushButton>
#include <QSignalBlocker>
#include <QSpinBox>
#include <QToolButton>
#include <QVBoxLayout>
#include <algorithm>

#include "formats/viewer_script_file.h"
#include "views/number_box.h"
#include "views/reprojection_controls.h"

namespace oflab {
namespace {

QString source_key(const std::string& kind, const std::string& name) {
  return QString::fromStdString(kind + "|" + name);
}

// The picker's entry of `name` of `kind` (a label without %1 names no file).
QString entry_label(const AnimationSourceKind& kind, const QString& name) {
  return QString::fromStdString(fill_pattern(kind.label, name.toStdString()));
}

// A menu of check boxes that stays open while they are checked and unchecked, so several
// policies can be picked in one visit; a click outside or Escape closes it.
class ChecklistMenu : public QMenu {
 public:
  using QMenu::QMenu;

 protected:
  void mouseReleaseEvent(QMouseEvent* event) override {
    if (!toggle(actionAt(event->pos()))) QMenu::mouseReleaseEvent(event);
  }
  void keyPressEvent(QKeyEvent* event) override {
    const int key = event->key();
    const bool press = key == Qt::Key_Return || key == Qt::Key_Enter || key == Qt::Key_Space;
    if (!press || !toggle(activeAction())) QMenu::keyPressEvent(event);
  }

 private:
  bool toggle(QAction* action) {
    if (!action || !action->isEnabled() || !action->isCheckable()) return false;
    action->trigger();
    return true;
  }
};

// The warp button's tooltip: what the warps compute now, in words.
QString warp_area_tooltip(WarpArea area) {
  return area == WarpArea::kVisible
             ? QObject::tr(
                   "Warp: what shows only. Each layer of a scene warps only the pixels "
                   "no nearer opaque layer covers; the frames are the same bytes as "
                   "the whole warp's, with fewer pixels computed")
             : QObject::tr(
                   "Warp: the whole layer. Each layer of a scene warps all its "
                   "pixels, those a nearer layer covers too");
}

void select_data(QComboBox* box, const QVariant& data) {
  const int index = box->findData(data);
  if (index >= 0) box->setCurrentIndex(index);
}

}  // namespace

AnimationControls::AnimationControls(QWidget* parent) : QWidget(parent) {
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->setSpacing(2);
  layout->addWidget(make_source_row());
  engine_rows_.push_back(make_mode_row());
  // The thresholds get their own row so the bar stays narrow enough for a 1280-pixel window.
  engine_rows_.push_back(make_threshold_row());
  for (QWidget* row : engine_rows_) layout->addWidget(row);
  set_settings(EngineSettings{});
  explain_controls();
}

void AnimationControls::set_engine_rows_shown(bool shown) {
  for (QWidget* row : engine_rows_) row->setVisible(shown);
}

void AnimationControls::explain_controls() {
  source_box_->setToolTip(
      tr("What plays: the scene panel's plane, a shipped script, scene or "
         "scene-shifting run, or a file"));
  viewer_box_->setToolTip(tr("The viewer's path through a scene (a viewer script)"));
  display_box_->setToolTip(tr("How the engine's frame and the exact projection are shown"));
  mode_box_->setToolTip(tr("The reuse policy: which update levels the engine may use"));
  delta_box_->setToolTip(
      tr("Delta: how much of the scaling the perspective cache takes from "
         "the affine warp (section 5.4.3)"));
  sampling_box_->setToolTip(tr(
      "Nearest, bilinear or mipmap sampling in the warps (mipmap filters a layer that shrinks)"));
  content_box_->setToolTip(
      tr("What a re-render draws, and so what it costs: the texture (one "
         "warp), a shaded brick lit per sample, or a facade impostor of "
         "lit, depth-tested boxes (manual/costs.md). A scene's polygons "
         "show the contents its file gives"));
  quality_box_->setToolTip(
      tr("The content's quality: samples per pixel of the shaded brick, "
         "detail of the impostor (1 + q storeys of 1 + 2q bays); a scene "
         "file's own quality wins. Dearer re-renders make reuse pay"));
}

QWidget* AnimationControls::make_source_row() {
  auto* row = new QWidget(this);
  auto* layout = new QHBoxLayout(row);
  layout->setContentsMargins(0, 0, 0, 0);
  source_box_ = new QComboBox(row);
  source_box_->setObjectName(QStringLiteral("animation_source"));
  for (const AnimationSourceKind& kind : animation_source_kinds()) {
    for (const std::string& n : kind.shipped_names()) {
      source_box_->addItem(entry_label(kind, QString::fromStdString(n)), source_key(kind.name, n));
    }
  }
  viewer_box_ = new QComboBox(row);
  viewer_box_->setObjectName(QStringLiteral("animation_viewer"));
  for (const std::string& n : shipped_viewer_script_names()) {
    viewer_box_->addItem(QString::fromStdString(n), QString::fromStdString(n));
  }
  select_data(viewer_box_, QStringLiteral("circle"));
  viewer_box_->setEnabled(false);
  display_box_ = new QComboBox(row);
  display_box_->setObjectName(QStringLiteral("animation_display"));
  display_box_->addItem(tr("Side by side"), int(PanelDisplay::kSideBySide));
  display_box_->addItem(tr("Difference heat map"), int(PanelDisplay::kDifference));
  display_box_->addItem(tr("Blink"), int(PanelDisplay::kBlink));
  display_box_->addItem(tr("Compare policies"), int(PanelDisplay::kComparison));
  display_box_->setItemData(display_box_->count() - 1,
                            tr("Plays the policies of the Policies menu at once beside the exact "
                               "projection, each with a difference heat map"),
                            Qt::ToolTipRole);
  layout->addWidget(new QLabel(tr("Play"), row));
  layout->addWidget(source_box_, 2);
  layout->addWidget(new QLabel(tr("viewer"), row));
  layout->addWidget(viewer_box_, 1);
  layout->addWidget(make_warp_area_button(row));
  layout->addWidget(new QLabel(tr("Show"), row));
  layout->addWidget(display_box_, 1);
  layout->addWidget(make_compare_button(row));
  for (QComboBox* box : {source_box_, viewer_box_, display_box_}) {
    // Long file names must not widen the window.
    box->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    box->setMinimumContentsLength(8);
  }
  connect(source_box_, QOverload<int>::of(&QComboBox::activated), this, [this] {
    // A kind picked anew starts on its own viewer script (scene shifting: train-sideways).
    const AnimationSourceKind& kind = current_kind();
    if (kind.uses_viewer && kind.name != shown_kind_) {
      select_data(viewer_box_, QString::fromStdString(kind.default_viewer));
    }
    show_kind(kind);
    emit source_edited();
  });
  connect(viewer_box_, QOverload<int>::of(&QComboBox::activated), this,
          [this] { emit source_edited(); });
  connect(display_box_, QOverload<int>::of(&QComboBox::activated), this,
          [this] { emit display_edited(); });
  return row;
}

QWidget* AnimationControls::make_mode_row() {
  auto* row = new QWidget(this);
  auto* layout = new QHBoxLayout(row);
  layout->setContentsMargins(0, 0, 0, 0);
  mode_box_ = new QComboBox(row);
  mode_box_->setObjectName(QStringLiteral("animation_mode"));
  for (const ReusePolicy& p : reuse_policies()) {
    mode_box_->addItem(p.name, QString(p.name));
    mode_box_->setItemData(mode_box_->count() - 1, QString(p.summary), Qt::ToolTipRole);
  }
  budget_box_ = new QSpinBox(row);
  budget_box_->setObjectName(QStringLiteral("animation_budget"));
  budget_box_->setRange(-1, 100000000);
  budget_box_->setSingleStep(1000);
  budget_box_->setSuffix(tr(" px/frame"));
  budget_box_->setSpecialValueText(tr("auto (a quarter of the frame)"));
  budget_box_->setKeyboardTracking(false);
  budget_box_->setToolTip(tr("The budget policy's pixels written per frame, shared by all layers"));
  connect(budget_box_, QOverload<int>::of(&QSpinBox::valueChanged), this,
          [this] { emit settings_edited(); });
  affine_switch_ = new QPushButton(tr("Affine/persp."), row);
  affine_switch_->setToolTip(tr("Switches between the affine and the perspective mode"));
  layout->addWidget(new QLabel(tr("Mode"), row));
  layout->addWidget(mode_box_);
  layout->addWidget(budget_box_);
  layout->addWidget(affine_switch_);
  delta_box_ = new QComboBox(row);
  for (DeltaPolicy d : delta_policies()) delta_box_->addItem(delta_policy_name(d), int(d));
  sampling_box_ = new QComboBox(row);
  for (int i = 0; i < kSamplingCount; ++i) {
    sampling_box_->addItem(sampling_name(Sampling(i)), i);
  }
  layout->addWidget(new QLabel(tr("Delta"), row));
  layout->addWidget(delta_box_);
  layout->addWidget(sampling_box_);
  // A short button (its menu holds the fields) so the bar still fits a 1024-pixel window.
  reprojection_ = new ReprojectionControls(row);
  layout->addWidget(reprojection_);
  connect(reprojection_, &ReprojectionControls::edited, this, [this] { emit settings_edited(); });
  layout->addStretch(1);
  connect_mode_controls();
  return row;
}

void AnimationControls::connect_mode_controls() {
  for (QComboBox* box : {mode_box_, delta_box_, sampling_box_}) {
    connect(box, QOverload<int>::of(&QComboBox::activated), this, [this] {
      show_budget();
      emit settings_edited();
    });
  }
  connect(affine_switch_, &QPushButton::clicked, this, [this] {
    const bool affine = mode_box_->currentData().toString() == QStringLiteral("affine");
    select_data(mode_box_, affine ? QStringLiteral("perspective") : QStringLiteral("affine"));
    show_budget();
    emit settings_edited();
  });
}

QToolButton* AnimationControls::make_warp_area_button(QWidget* parent) {
  // A short button with a menu, not a box: the row must still fit a 1024-pixel window.
  warp_area_button_ = new QToolButton(parent);
  warp_area_button_->setObjectName(QStringLiteral("animation_warp_area"));
  warp_area_button_->setText(tr("Warp"));
  warp_area_button_->setPopupMode(QToolButton::InstantPopup);
  auto* menu = new QMenu(warp_area_button_);
  auto* group = new QActionGroup(menu);
  const QString labels[kWarpAreaCount] = {tr("The whole layer"),
                                          tr("What shows only (pixels no nearer layer covers)")};
  for (int i = 0; i < kWarpAreaCount; ++i) {
    QAction* action = menu->addAction(labels[i]);
    action->setCheckable(true);
    action->setData(QString::fromLatin1(warp_area_name(WarpArea(i))));
    group->addAction(action);
    warp_area_actions_.push_back(action);
    connect(action, &QAction::triggered, this, [this] {
      warp_area_button_->setToolTip(warp_area_tooltip(warp_area()));
      emit settings_edited();
    });
  }
  warp_area_button_->setMenu(menu);
  return warp_area_button_;
}

WarpArea AnimationControls::warp_area() const {
  for (int i = 0; i < kWarpAreaCount; ++i) {
    if (warp_area_actions_[size_t(i)]->isChecked()) return WarpArea(i);
  }
  return WarpArea::kWhole;
}

QWidget* AnimationControls::make_threshold_row() {
  auto* threshold_row = new QWidget(this);
  auto* thresholds = new QHBoxLayout(threshold_row);
  thresholds->setContentsMargins(0, 0, 0, 0);
  auto* label = new QLabel(tr("Thresholds (px)"), threshold_row);
  label->setToolTip(tr("Error budgets of the levels none, translate, affine and perspective"));
  thresholds->addWidget(label);
  for (int k = 0; k < kTermCount; ++k) {
    // Any number can be typed: the model refuses one outside limits::kThreshold.
    thresholds_[k] = new NumberBox(0.0, 100.0, threshold_row);
    thresholds_[k]->setObjectName(QStringLiteral("animation_threshold_%1").arg(k));
    thresholds_[k]->setDecimals(2);
    thresholds_[k]->setSingleStep(0.25);
    thresholds_[k]->setToolTip(tr("Threshold of level %1, pixels").arg(level_name(Level(k))));
    thresholds->addWidget(thresholds_[k]);
    connect(thresholds_[k], QOverload<double>::of(&QDoubleSpinBox::valueChanged), this,
            [this] { emit settings_edited(); });
  }
  add_content_controls(threshold_row, thresholds);
  thresholds->addStretch(1);
  return threshold_row;
}

void AnimationControls::add_content_controls(QWidget* row, QHBoxLayout* layout) {
  content_box_ = new QComboBox(row);
  content_box_->setObjectName(QStringLiteral("animation_content"));
  for (ContentKind kind : content_kinds()) {
    content_box_->addItem(content_name(kind), int(kind));
  }
  quality_box_ = new QSpinBox(row);
  quality_box_->setObjectName(QStringLiteral("animation_quality"));
  quality_box_->setRange(1, kMaxContentQuality);
  quality_box_->setKeyboardTracking(false);
  // No labels: the entries name the contents and the spin box says "quality", so the row
  // still fits a 1024-pixel window.
  quality_box_->setPrefix(tr("quality "));
  layout->addWidget(content_box_);
  layout->addWidget(quality_box_);
  connect(content_box_, QOverload<int>::of(&QComboBox::activated), this,
          [this] { emit settings_edited(); });
  connect(quality_box_, QOverload<int>::of(&QSpinBox::valueChanged), this,
          [this] { emit settings_edited(); });
}

EngineSettings AnimationControls::settings() const {
  EngineSettings s;
  s.policy = find_reuse_policy(mode_box_->currentData().toString().toStdString());
  if (!s.policy) s.policy = &default_reuse_policy();  // the box lists the registry only
  for (int k = 0; k < kTermCount; ++k) s.thresholds[size_t(k)] = thresholds_[k]->value();
  s.delta = static_cast<DeltaPolicy>(delta_box_->currentData().toInt());
  s.sampling = static_cast<Sampling>(sampling_box_->currentData().toInt());
  s.warp_area = warp_area();
  s.content.kind = static_cast<ContentKind>(content_box_->currentData().toInt());
  s.content.quality = quality_box_->value();
  reprojection_->read_into(s);
  if (s.policy->shares_budget && budget_box_->value() >= 0) {
    s.budget = {FrameBudget::Unit::kPixels, double(budget_box_->value())};
  }
  return s;
}

void AnimationControls::show_budget() {
  const ReusePolicy* p = find_reuse_policy(mode_box_->currentData().toString().toStdString());
  budget_box_->setVisible(p && p->shares_budget);
}

void AnimationControls::set_settings(const EngineSettings& s) {
  const QSignalBlocker b0(mode_box_), b1(delta_box_), b2(sampling_box_), b3(content_box_),
      b4(quality_box_);
  select_data(mode_box_, QString(s.policy->name));
  select_data(delta_box_, int(s.delta));
  select_data(sampling_box_, int(s.sampling));
  warp_area_actions_[size_t(s.warp_area)]->setChecked(true);  // triggers no signal
  warp_area_button_->setToolTip(warp_area_tooltip(s.warp_area));
  select_data(content_box_, int(s.content.kind));
  quality_box_->setValue(s.content.quality);
  for (int k = 0; k < kTermCount; ++k) {
    const QSignalBlocker block(thresholds_[k]);
    thresholds_[k]->setValue(s.thresholds[size_t(k)]);
  }
  // A time budget has no box here: the GUI edits pixel budgets (auto for none).
  const QSignalBlocker block(budget_box_);
  const bool pixels = s.budget.unit == FrameBudget::Unit::kPixels;
  budget_box_->setValue(pixels ? static_cast<int>(std::min(s.budget.amount, 1e8)) : -1);
  show_budget();
  reprojection_->show_settings(s);
}

QToolButton* AnimationControls::make_compare_button(QWidget* parent) {
  compare_button_ = new QToolButton(parent);
  compare_button_->setObjectName(QStringLiteral("animation_compared"));
  compare_button_->setText(tr("Policies"));
  compare_button_->setPopupMode(QToolButton::InstantPopup);
  compare_button_->setToolTip(
      tr("The reuse policies the comparison plays: 1 to %1 of them").arg(kMaxComparedPolicies));
  auto* menu = new ChecklistMenu(compare_button_);
  menu->setObjectName(QStringLiteral("animation_compared_menu"));
  for (const ReusePolicy& p : reuse_policies()) {
    QAction* action = menu->addAction(QString(p.name));
    action->setCheckable(true);
    action->setData(QString(p.name));
    action->setToolTip(QString(p.summary));
    compare_actions_.push_back(action);
    connect(action, &QAction::triggered, this, [this, action] { compared_toggled(action); });
  }
  menu->setToolTipsVisible(true);
  compare_button_->setMenu(menu);
  return compare_button_;
}

void AnimationControls::compared_toggled(QAction* action) {
  const int checked = static_cast<int>(compared().size());
  if (checked < 1 || checked > kMaxComparedPolicies) {
    const QSignalBlocker block(action);
    action->setChecked(!action->isChecked());  // refused: the comparison keeps 1 .. 4
    emit refused(tr("Policies: the comparison plays 1 to %1 policies; %2")
                     .arg(kMaxComparedPolicies)
                     .arg(checked < 1 ? tr("check another before unchecking this one")
                                      : tr("uncheck one before checking another")));
    return;
  }
  emit compared_edited();
}

std::vector<const ReusePolicy*> AnimationControls::compared() const {
  std::vector<const ReusePolicy*> out;
  for (QAction* a : compare_actions_) {
    if (a->isChecked()) out.push_back(find_reuse_policy(a->data().toString().toStdString()));
  }
  return out;
}

void AnimationControls::set_compared(const std::vector<const ReusePolicy*>& policies) {
  for (QAction* a : compare_actions_) {
    const QSignalBlocker block(a);
    const ReusePolicy* p = find_reuse_policy(a->data().toString().toStdString());
    a->setChecked(std::find(policies.begin(), policies.end(), p) != policies.end());
  }
}

PanelDisplay AnimationControls::display() const {
  return static_cast<PanelDisplay>(display_box_->currentData().toInt());
}

void AnimationControls::set_display(PanelDisplay display) {
  const QSignalBlocker block(display_box_);
  select_data(display_box_, int(display));
}

const AnimationSourceKind& AnimationControls::current_kind() const {
  const std::string name = source_box_->currentData().toString().section('|', 0, 0).toStdString();
  return *find_animation_source_kind(name);  // every entry comes from the table
}

SourceChoice AnimationControls::source() const {
  SourceChoice choice;
  choice.kind = current_kind().name;
  choice.name = source_box_->currentData().toString().section('|', 1).toStdString();
  if (current_kind().uses_viewer) {
    choice.viewer = viewer_box_->currentData().toString().toStdString();
  }
  return choice;
}

void AnimationControls::add_file_entry(QComboBox* box, const std::string& kind,
                                       const std::string& path) {
  const QString file = tr("file %1").arg(QString::fromStdString(path));
  if (kind.empty()) {
    if (box->findData(QString::fromStdString(path)) < 0)
      box->addItem(file, QString::fromStdString(path));
    return;
  }
  const AnimationSourceKind* entry = find_animation_source_kind(kind);
  if (!entry || box->findData(source_key(kind, path)) >= 0) return;
  box->addItem(entry_label(*entry, file), source_key(kind, path));
}

void AnimationControls::set_source(const SourceChoice& choice) {
  const QSignalBlocker b0(source_box_), b1(viewer_box_);
  add_file_entry(source_box_, choice.kind, choice.name);
  select_data(source_box_, source_key(choice.kind, choice.name));
  const AnimationSourceKind& kind = current_kind();
  if (kind.uses_viewer) {
    add_file_entry(viewer_box_, "", choice.viewer);
    select_data(viewer_box_, QString::fromStdString(choice.viewer));
  }
  show_kind(kind);
  shown_kind_ = kind.name;
}

void AnimationControls::show_kind(const AnimationSourceKind& kind) {
  viewer_box_->setEnabled(kind.uses_viewer);
  // Scene shifting keeps its own tolerance: the policy, thresholds and Delta do not apply.
  for (QWidget* w : std::initializer_list<QWidget*>{mode_box_, affine_switch_, delta_box_}) {
    w->setEnabled(kind.uses_reuse_policy);
  }
  for (QDoubleSpinBox* t : thresholds_) t->setEnabled(kind.uses_reuse_policy);
  // A scene's polygons show the contents of its file; a single plane shows the chosen one.
  content_box_->setEnabled(!kind.uses_viewer);
  // Only a scene's layers can hide each other: the warp area is theirs.
  warp_area_button_->setEnabled(kind.uses_viewer && kind.uses_reuse_policy);
}

}  // namespace oflab

#include "models/window_model.h"

#include <algorithm>
#include <stdexcept>

#include "adapters/exact_frames.h"
#include "adapters/frame_images.h"
#include "adapters/texture.h"
#include "engine/reuse_policy.h"
#include "flow/limits.h"
#include "formats/datasets.h"
#include "formats/script_file.h"
#include "lessons/lessons.h"
#include "models/animation_model.h"
#include "models/scene_model.h"
#include "player/lab.h"
#include "player/policy_comparison.h"

namespace oflab {

WindowModel::WindowModel(std::vector<std::string> view_names, QObject* parent)
    : QObject(parent), view_names_(std::move(view_names)) {
  default_texture_ = default_texture();
  lab_ = std::make_unique<Lab>(
      image_from_qimage(default_texture_), [this](const std::string& path, std::string* error) {
        QString why;
        loaded_texture_ = load_texture_image(QString::fromStdString(path), &why);
        if (loaded_texture_.isNull()) *error = why.toStdString();
        return loaded_texture_.isNull() ? Image() : image_from_qimage(loaded_texture_);
      });
  lab_->set_front_end_check([this](const WindowState& s) { return front_end_problem(s); });
  scene_ = new SceneModel(&lab_->panel(), default_texture_, this);
  animation_ = new AnimationModel(&lab_->run(), scene_, this);
  values().view = view_names_.empty() ? WindowState().view : view_names_.front();
  connect(animation_, &AnimationModel::source_changed, this,
          [this] { lab_->comparison().reset(); });
  connect(animation_, &AnimationModel::input_rejected, this, &WindowModel::input_rejected);
  connect(scene_, &SceneModel::scene_rejected, this, &WindowModel::input_rejected);
}

WindowModel::~WindowModel() = default;

const WindowState& WindowModel::values() const { return lab_->values(); }
WindowState& WindowModel::values() { return lab_->values(); }

PolicyComparison& WindowModel::comparison() const { return lab_->comparison(); }

WindowState WindowModel::state() const { return lab_->state(); }

std::string WindowModel::front_end_problem(const WindowState& s) const {
  if (std::find(view_names_.begin(), view_names_.end(), s.view) == view_names_.end()) {
    return "view: unknown view '" + s.view + "' (one of " + joined_names(view_names_) + ")";
  }
  if (!find_exact_renderer(s.exact_renderer)) {
    return "animation.exact_renderer: unknown renderer '" + s.exact_renderer + "' (one of " +
           exact_renderer_names() + ")";
  }
  return "";
}

bool WindowModel::apply(const WindowState& s, QString* error) {
  const std::string problem = lab_->apply(s);
  if (!problem.empty()) {
    *error = QString::fromStdString(problem);
    return false;
  }
  scene_->panel_replaced(s.texture.empty() ? default_texture_ : loaded_texture_);
  animation_->run_replaced();
  emit flow_display_changed();
  emit basis_changed();
  emit explorer_changed();
  emit panels_changed();
  emit presentation_changed();
  emit scene_panel_changed();
  emit layout_changed();
  emit world_camera_changed();
  emit play_changed();
  emit lesson_changed();
  emit study_changed();
  emit view_changed();
  return true;
}

bool WindowModel::set_view(const std::string& name) {
  if (std::find(view_names_.begin(), view_names_.end(), name) == view_names_.end()) {
    emit input_rejected(QString::fromStdString("view: unknown view '" + name + "' (one of " +
                                               joined_names(view_names_) + ")"));
    return false;
  }
  if (name == values().view) return true;
  values().view = name;
  emit view_changed();
  return true;
}

void WindowModel::set_flow_display(const FlowDisplay& display) {
  values().flow = display;
  emit flow_display_changed();
}

void WindowModel::set_basis(BasisKind basis) {
  values().basis = basis;
  emit basis_changed();
}

void WindowModel::set_basis_playing(bool playing) {
  values().basis_playing = playing;
  emit basis_changed();
}

void WindowModel::set_basis_explorer(bool on) {
  values().basis_explorer = on;
  emit explorer_changed();
}

bool WindowModel::set_explorer_term(int index, double value) {
  if (index < 0 || index >= kExplorerTermCount) return false;
  ExplorerTerms terms = values().explorer_terms;
  terms[size_t(index)] = value;
  return set_explorer_terms(terms);
}

bool WindowModel::set_explorer_terms(const ExplorerTerms& terms) {
  const std::string problem = explorer_terms_problem(terms);
  if (!problem.empty()) {
    emit input_rejected(QString::fromStdString(problem));
    return false;
  }
  values().explorer_terms = terms;
  emit explorer_changed();
  return true;
}

void WindowModel::set_panel_display(PanelDisplay display) {
  values().display = display;
  emit panels_changed();
}

std::vector<std::string> WindowModel::compared() const {
  std::vector<std::string> names;
  for (const ReusePolicy* policy : comparison().policies()) names.push_back(policy->name);
  return names;
}

bool WindowModel::set_compared(const std::vector<std::string>& names) {
  WindowState check;
  check.compared = names;
  const std::string problem_text = window_state_problem(check);
  if (!problem_text.empty()) {
    emit input_rejected(QString::fromStdString(problem_text));
    return false;
  }
  comparison().set_policies(policies_named(names));
  emit panels_changed();
  return true;
}

bool WindowModel::set_exact_renderer(const std::string& name) {
  if (!find_exact_renderer(name)) {
    emit input_rejected(QString::fromStdString("animation.exact_renderer: unknown renderer '" +
                                               name + "' (one of " + exact_renderer_names() + ")"));
    return false;
  }
  values().exact_renderer = name;
  emit panels_changed();
  return true;
}

void WindowModel::set_framing(PanelFraming framing) {
  values().framing = framing;
  emit panels_changed();
}

bool WindowModel::set_zoom(double zoom) {
  const std::string problem_text = limits::kZoom.problem(zoom);
  if (!problem_text.empty()) {
    emit input_rejected(QString::fromStdString("zoom: " + problem_text));
    return false;
  }
  values().zoom = zoom;
  emit panels_changed();
  return true;
}

void WindowModel::set_presentation(bool on) {
  values().presentation = on;
  emit presentation_changed();
}

void WindowModel::set_scene_panel(bool shown) {
  if (shown == values().scene_panel) return;
  values().scene_panel = shown;
  emit scene_panel_changed();
}

void WindowModel::set_cause_and_effect(bool shown) {
  if (shown == values().cause_and_effect) return;
  values().cause_and_effect = shown;
  emit layout_changed();
}

void WindowModel::set_world_camera(WorldCamera camera) {
  if (camera == values().world_camera) return;
  values().world_camera = camera;
  emit world_camera_changed();
}

bool WindowModel::set_play_rate(int frames_per_second) {
  const std::string problem_text = limits::kPlayRate.problem(frames_per_second);
  if (!problem_text.empty()) {
    emit input_rejected(QString::fromStdString("play rate: " + problem_text));
    return false;
  }
  values().play_rate = frames_per_second;
  emit play_changed();
  return true;
}

bool WindowModel::set_lesson_step(int step) {
  const Lesson* lesson = values().lesson.empty() ? nullptr : find_lesson(values().lesson);
  if (step < 0 || (!lesson && step != 0) || (lesson && step > int(lesson->steps.size()))) {
    emit input_rejected(QStringLiteral("lesson step %1 does not exist").arg(step));
    return false;
  }
  values().lesson_step = step;
  emit lesson_changed();
  return true;
}

void WindowModel::set_playing(bool playing) {
  if (playing == values().playing) return;
  values().playing = playing;
  emit play_changed();
}

}  // namespace oflab

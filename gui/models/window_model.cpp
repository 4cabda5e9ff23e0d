#include "models/window_model.h"

#include <algorithm>
#include <stdexcept>

#include "adapters/exact_frames.h"
#include "adapters/texture.h"
#include "engine/reuse_policy.h"
#include "flow/limits.h"
#include "formats/datasets.h"
#include "formats/script_file.h"
#include "models/animation_model.h"
#include "models/lessons.h"
#include "models/policy_comparison.h"
#include "models/scene_model.h"

namespace oflab {
namespace {

std::vector<const ReusePolicy*> policies_of(const std::vector<std::string>& names) {
  std::vector<const ReusePolicy*> policies;
  for (const std::string& name : names) policies.push_back(&reuse_policy(name));
  return policies;
}

}  // namespace

WindowModel::WindowModel(std::vector<std::string> view_names, QObject* parent)
    : QObject(parent),
      view_names_(std::move(view_names)),
      scene_(new SceneModel(this)),
      animation_(new AnimationModel(scene_, this)),
      comparison_(std::make_unique<PolicyComparison>(animation_)) {
  const WindowState defaults;
  view_ = view_names_.empty() ? defaults.view : view_names_.front();
  comparison_->set_policies(policies_of(defaults.compared));
  connect(animation_, &AnimationModel::source_changed, this, [this] { comparison_->reset(); });
  connect(animation_, &AnimationModel::input_rejected, this, &WindowModel::input_rejected);
  connect(scene_, &SceneModel::scene_rejected, this, &WindowModel::input_rejected);
}

WindowModel::~WindowModel() = default;

WindowState WindowModel::state() const {
  WindowState s;
  s.view = view_;
  s.flow = flow_;
  s.basis = basis_;
  s.basis_playing = basis_playing_;
  s.basis_explorer = basis_explorer_;
  s.explorer_terms = explorer_terms_;
  s.plane = scene_->scene();
  s.script = scene_->script() ? scene_->script_name().toStdString() : std::string();
  s.texture = scene_->texture_source().toStdString();
  s.source = animation_->source();
  s.settings = animation_->settings();
  s.display = display_;
  s.compared = compared();
  s.exact_renderer = exact_renderer_;
  s.zoom = zoom_;
  s.presentation = presentation_;
  s.scene_panel = scene_panel_;
  s.cause_and_effect = cause_and_effect_;
  s.play_rate = play_rate_;
  s.playing = playing_;
  s.frame = scene_->frame();
  s.lesson = lesson_;
  s.lesson_step = lesson_step_;
  return s;
}

std::string WindowModel::problem(const WindowState& s) const {
  const std::string limits_problem = window_state_problem(s);
  if (!limits_problem.empty()) return limits_problem;
  if (std::find(view_names_.begin(), view_names_.end(), s.view) == view_names_.end()) {
    return "view: unknown view '" + s.view + "' (one of " + joined_names(view_names_) + ")";
  }
  if (!find_exact_renderer(s.exact_renderer)) {
    return "animation.exact_renderer: unknown renderer '" + s.exact_renderer + "' (one of " +
           exact_renderer_names() + ")";
  }
  const Lesson* lesson = s.lesson.empty() ? nullptr : find_lesson(s.lesson);
  if (!s.lesson.empty() && !lesson) {
    return "lesson: unknown lesson '" + s.lesson + "' (one of " + lesson_names() + ")";
  }
  if (lesson && s.lesson_step > int(lesson->steps.size())) {
    return "lesson_step: " + std::to_string(s.lesson_step) + " is beyond the " +
           std::to_string(lesson->steps.size()) + " steps of " + s.lesson;
  }
  if (!find_animation_source_kind(s.source.kind)) {
    return "animation.source.kind: unknown kind '" + s.source.kind + "' (one of " +
           animation_source_kind_names() + ")";
  }
  const std::string source = animation_->source_problem(s.source, s.settings);
  return source.empty() ? source : "animation.source: " + source;
}

bool WindowModel::apply(const WindowState& s, QString* error) {
  std::string problem_text = problem(s);
  QImage texture;
  std::optional<MotionScript> script;
  if (problem_text.empty() && !s.texture.empty()) {
    texture = load_texture_image(QString::fromStdString(s.texture), error);
    if (texture.isNull()) problem_text = "texture: " + error->toStdString();
  }
  if (problem_text.empty() && !s.script.empty()) {
    try {
      script = read_script_file(resolve_script_path(s.script));
    } catch (const std::runtime_error& e) {
      problem_text = std::string("script: ") + e.what();
    }
  }
  if (!problem_text.empty()) {
    *error = QString::fromStdString(problem_text);
    return false;
  }
  if (!texture.isNull()) scene_->set_texture(texture, QString::fromStdString(s.texture));
  if (s.texture.empty() && !scene_->texture_source().isEmpty()) {
    scene_->set_texture(default_texture(), QString());
  }
  PlaneScene plane = s.plane;
  plane.pose.texture_size = scene_->scene().pose.texture_size;  // the texture's own size
  scene_->set_scene(plane);
  if (script) scene_->set_script(*script, QString::fromStdString(s.script));
  animation_->set_settings(s.settings);
  animation_->set_source(s.source);
  comparison_->set_policies(policies_of(s.compared));
  comparison_->reset();
  scene_->set_frame(s.frame);
  flow_ = s.flow;
  basis_ = s.basis;
  basis_playing_ = s.basis_playing;
  basis_explorer_ = s.basis_explorer;
  explorer_terms_ = s.explorer_terms;
  display_ = s.display;
  exact_renderer_ = s.exact_renderer;
  zoom_ = s.zoom;
  presentation_ = s.presentation;
  scene_panel_ = s.scene_panel;
  cause_and_effect_ = s.cause_and_effect;
  play_rate_ = s.play_rate;
  playing_ = s.playing;
  view_ = s.view;
  lesson_ = s.lesson;
  lesson_step_ = s.lesson_step;
  emit flow_display_changed();
  emit basis_changed();
  emit explorer_changed();
  emit panels_changed();
  emit presentation_changed();
  emit scene_panel_changed();
  emit layout_changed();
  emit play_changed();
  emit lesson_changed();
  emit view_changed();
  return true;
}

bool WindowModel::set_view(const std::string& name) {
  if (std::find(view_names_.begin(), view_names_.end(), name) == view_names_.end()) {
    emit input_rejected(QString::fromStdString("view: unknown view '" + name + "' (one of " +
                                               joined_names(view_names_) + ")"));
    return false;
  }
  if (name == view_) return true;
  view_ = name;
  emit view_changed();
  return true;
}

void WindowModel::set_flow_display(const FlowDisplay& display) {
  flow_ = display;
  emit flow_display_changed();
}

void WindowModel::set_basis(BasisKind basis) {
  basis_ = basis;
  emit basis_changed();
}

void WindowModel::set_basis_playing(bool playing) {
  basis_playing_ = playing;
  emit basis_changed();
}

void WindowModel::set_basis_explorer(bool on) {
  basis_explorer_ = on;
  emit explorer_changed();
}

bool WindowModel::set_explorer_term(int index, double value) {
  if (index < 0 || index >= kExplorerTermCount) return false;
  ExplorerTerms terms = explorer_terms_;
  terms[size_t(index)] = value;
  return set_explorer_terms(terms);
}

bool WindowModel::set_explorer_terms(const ExplorerTerms& terms) {
  const std::string problem = explorer_terms_problem(terms);
  if (!problem.empty()) {
    emit input_rejected(QString::fromStdString(problem));
    return false;
  }
  explorer_terms_ = terms;
  emit explorer_changed();
  return true;
}

void WindowModel::set_panel_display(PanelDisplay display) {
  display_ = display;
  emit panels_changed();
}

std::vector<std::string> WindowModel::compared() const {
  std::vector<std::string> names;
  for (const ReusePolicy* policy : comparison_->policies()) names.push_back(policy->name);
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
  comparison_->set_policies(policies_of(names));
  emit panels_changed();
  return true;
}

bool WindowModel::set_exact_renderer(const std::string& name) {
  if (!find_exact_renderer(name)) {
    emit input_rejected(QString::fromStdString("animation.exact_renderer: unknown renderer '" +
                                               name + "' (one of " + exact_renderer_names() + ")"));
    return false;
  }
  exact_renderer_ = name;
  emit panels_changed();
  return true;
}

bool WindowModel::set_zoom(double zoom) {
  const std::string problem_text = limits::kZoom.problem(zoom);
  if (!problem_text.empty()) {
    emit input_rejected(QString::fromStdString("zoom: " + problem_text));
    return false;
  }
  zoom_ = zoom;
  emit panels_changed();
  return true;
}

void WindowModel::set_presentation(bool on) {
  presentation_ = on;
  emit presentation_changed();
}

void WindowModel::set_scene_panel(bool shown) {
  if (shown == scene_panel_) return;
  scene_panel_ = shown;
  emit scene_panel_changed();
}

void WindowModel::set_cause_and_effect(bool shown) {
  if (shown == cause_and_effect_) return;
  cause_and_effect_ = shown;
  emit layout_changed();
}

bool WindowModel::set_play_rate(int frames_per_second) {
  const std::string problem_text = limits::kPlayRate.problem(frames_per_second);
  if (!problem_text.empty()) {
    emit input_rejected(QString::fromStdString("play rate: " + problem_text));
    return false;
  }
  play_rate_ = frames_per_second;
  emit play_changed();
  return true;
}

bool WindowModel::set_lesson_step(int step) {
  const Lesson* lesson = lesson_.empty() ? nullptr : find_lesson(lesson_);
  if (step < 0 || (!lesson && step != 0) || (lesson && step > int(lesson->steps.size()))) {
    emit input_rejected(QStringLiteral("lesson step %1 does not exist").arg(step));
    return false;
  }
  lesson_step_ = step;
  emit lesson_changed();
  return true;
}

void WindowModel::set_playing(bool playing) {
  if (playing == playing_) return;
  playing_ = playing;
  emit play_changed();
}

}  // namespace oflab

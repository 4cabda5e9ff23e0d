#include "player/lab.h"

#include <stdexcept>

#include "formats/datasets.h"
#include "formats/image_io.h"
#include "formats/script_file.h"
#include "lessons/lessons.h"

namespace oflab {

Image shipped_default_texture() { return read_image(default_texture_path()); }

Image read_texture_file(const std::string& path, std::string* error) {
  try {
    return read_image(path);
  } catch (const std::exception& e) {
    if (error) *error = e.what();
  }
  return Image();
}

std::vector<const ReusePolicy*> policies_named(const std::vector<std::string>& names) {
  std::vector<const ReusePolicy*> policies;
  for (const std::string& name : names) policies.push_back(&reuse_policy(name));
  return policies;
}

Lab::Lab(Image default_texture, TextureReader read_texture)
    : default_texture_(default_texture),
      read_texture_(read_texture ? std::move(read_texture) : read_texture_file),
      panel_(std::move(default_texture)),
      run_(&panel_),
      comparison_(&run_) {
  comparison_.set_policies(policies_named(values_.compared));
}

WindowState Lab::state() const {
  WindowState s = values_;
  s.plane = panel_.scene();
  s.script = panel_.script() ? panel_.script_name() : std::string();
  s.texture = panel_.texture_source();
  s.source = run_.source();
  s.settings = run_.settings();
  s.compared.clear();
  for (const ReusePolicy* policy : comparison_.policies()) {
    s.compared.push_back(policy->name);
  }
  s.frame = panel_.frame();
  return s;
}

std::string Lab::problem(const WindowState& s) const {
  const std::string limits_problem = window_state_problem(s);
  if (!limits_problem.empty()) return limits_problem;
  if (front_end_check_) {
    const std::string front_end = front_end_check_(s);
    if (!front_end.empty()) return front_end;
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
  const std::string source = run_.source_problem(s.source, s.settings);
  return source.empty() ? source : "animation.source: " + source;
}

std::string Lab::read_inputs(const WindowState& s, Image* texture,
                             std::optional<MotionScript>* script) const {
  if (!s.texture.empty()) {
    std::string error;
    *texture = read_texture_(resolve_texture_path(s.texture), &error);
    if (texture->empty()) return "texture: " + error;
  }
  if (!s.script.empty()) {
    try {
      *script = read_script_file(resolve_script_path(s.script));
    } catch (const std::runtime_error& e) {
      return std::string("script: ") + e.what();
    }
  }
  return "";
}

std::string Lab::apply(const WindowState& s) {
  Image texture;
  std::optional<MotionScript> script;
  std::string problem_text = problem(s);
  if (problem_text.empty()) problem_text = read_inputs(s, &texture, &script);
  if (!problem_text.empty()) return problem_text;
  if (!texture.empty()) panel_.set_texture(std::move(texture), s.texture);
  if (s.texture.empty() && !panel_.texture_source().empty()) {
    panel_.set_texture(default_texture_, "");
  }
  PlaneScene plane = s.plane;
  plane.pose.texture_size = panel_.scene().pose.texture_size;  // the texture's own size
  panel_.set_scene(plane);
  if (script) panel_.set_script(*script, s.script);
  run_.set_settings(s.settings);
  run_.set_source(s.source);
  comparison_.set_policies(policies_named(s.compared));
  comparison_.reset();
  panel_.set_frame(s.frame);
  values_ = s;
  return "";
}

}  // namespace oflab

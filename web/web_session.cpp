#include "web_session.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <utility>

#include "basis/basis_catalog.h"
#include "display/flow_parts.h"
#include "engine/reuse_policy.h"
#include "flow/basis.h"
#include "flow/flow_field.h"
#include "formats/datasets.h"
#include "formats/image_io.h"
#include "formats/script_file.h"
#include "frame_pixels.h"
#include "image/image_compare.h"
#include "player/source_length.h"
#include "state/state_fields.h"
#include "state/window_state_file.h"

namespace oflab {
namespace {

using json = nlohmann::json;

// The page's background behind transparent frame pixels (the style sheet's panel colour).
constexpr std::uint8_t kBackground[3] = {24, 27, 31};
// Largest side of a comparison panel, display pixels.
constexpr int kMaxPanelSide = 4096;
// Grey levels of difference at the top of the heat map's ramp.
constexpr int kHeatFullScale = 64;
// The policy whose runs draw the exact projection: every frame rendered exactly.
constexpr const char* kExactPolicy = "rerender";

json point_json(const Vec2& p) { return json::array({p.x, p.y}); }

json coefficients_json(const PlanarFlowCoefficients& c) {
  return {{"tx", c.tx},   {"ty", c.ty},   {"j11", c.j11}, {"j12", c.j12},
          {"j21", c.j21}, {"j22", c.j22}, {"px", c.px},   {"py", c.py}};
}

json planar_basis_json(const PlanarBasisTerms& p) {
  return {{"tx", p.tx},
          {"ty", p.ty},
          {"scale", p.scale},
          {"squash", p.squash},
          {"shear", p.shear},
          {"rotation", p.rotation},
          {"v1_yy", p.v1_yy},
          {"v2_xx", p.v2_xx},
          {"non_planar_x", p.non_planar_x},
          {"non_planar_y", p.non_planar_y},
          {"px", p.px},
          {"py", p.py}};
}

// The fields of a state object that the comparison's runs do not depend on.
const std::vector<std::string>& display_only_fields() {
  static const std::vector<std::string> fields = {
      "view",        "frame",          "flow",         "basis",  "basis_playing", "presentation",
      "scene_panel", "play_rate",      "playing",      "lesson", "lesson_step",   "zoom",
      "display",     "exact_renderer", "world_camera", "framing"};
  return fields;
}

json run_defining_fields(const WindowState& state) {
  json object = window_state_object(state);
  for (const std::string& field : display_only_fields()) {
    object.erase(field);
    object["animation"].erase(field);
  }
  return object;
}

json lesson_json(const Lesson& lesson) {
  json steps = json::array();
  for (const LessonStep& step : lesson.steps) {
    json says = json::array();
    for (const LessonClaim& claim : step.claims) says.push_back(claim.says);
    steps.push_back({{"say", step.say},
                     {"frame", step.frame},
                     {"play", step.play},
                     {"state", step.has_state ? window_state_object(step.state) : json()},
                     {"claims", says}});
  }
  return {{"name", lesson.name},
          {"title", lesson.title},
          {"narrative", lesson.narrative},
          {"order", lesson.order},
          {"play", lesson.play},
          {"state", window_state_object(lesson.state)},
          {"steps", steps}};
}

MotionScript read_shipped_or_file_script(const std::string& name) {
  return read_script_file(resolve_script_path(name));
}

}  // namespace

WebSession::WebSession() : texture_(read_image(default_texture_path())), panel_(texture_) {
  state_.plane.pose.texture_size = {texture_.width(), texture_.height()};
  rebuild_comparison();
}

WindowState WebSession::shown_state() const {
  WindowState shown = state_;
  shown.frame = panel_.frame();
  return shown;
}

std::string WebSession::state_json() const { return window_state_object(shown_state()).dump(); }

std::string WebSession::set_state(const std::string& object_json, const std::string& origin) {
  try {
    const json object = json::parse(object_json);
    const std::string problem =
        apply_state(read_window_state_object(object, origin, "state", WindowState{}));
    return problem.empty() ? problem : origin + ": " + problem;
  } catch (const std::exception& e) {
    return e.what();
  }
}

std::string WebSession::apply_state(WindowState next) {
  try {
    next.plane.pose.texture_size = {texture_.width(), texture_.height()};
    for (const std::string* name : {&next.script, &next.source.name}) {
      if (!name->empty() && scripts_.count(*name) == 0 &&
          (name == &next.script || next.source.kind == "script")) {
        scripts_[*name] = read_shipped_or_file_script(*name);
      }
    }
    std::string problem = window_state_problem(next);
    if (!problem.empty()) return problem;
    // The frame clock as the desktop's: the plane, its script, the source's loop.
    PlanePanel panel = panel_;
    problem = panel.set_scene(next.plane);
    if (problem.empty() && !next.script.empty()) {
      problem = panel.set_script(scripts_.at(next.script), next.script);
    }
    if (!problem.empty()) return problem;
    panel.set_loop_override(source_frame_count(next.source, panel));
    panel.set_frame(next.frame);
    const bool rebuild = run_defining_fields(next) != run_defining_fields(state_);
    state_ = std::move(next);
    panel_ = std::move(panel);
    if (rebuild) rebuild_comparison();
    return "";
  } catch (const std::exception& e) {
    return e.what();
  }
}

void WebSession::stage_play(int frames) {
  for (int k = 0; k < frames; ++k) panel_.set_frame(panel_.frame() + 1);
}

std::string WebSession::go_to_lesson(const std::string& name, int step) {
  const Lesson* lesson = find_lesson(name);
  if (!lesson) return "unknown lesson '" + name + "' (one of " + lesson_names() + ")";
  try {
    return go_to_lesson_step(*this, *lesson, step);
  } catch (const std::exception& e) {
    return e.what();
  }
}

std::string WebSession::state_schema_json() { return state_schema().dump(); }

std::string WebSession::add_script(const std::string& text, const std::string& origin) {
  try {
    MotionScript script = parse_script(text, origin);
    const std::string name = script.name.empty() ? origin : script.name;
    scripts_[name] = std::move(script);
    return "";
  } catch (const std::exception& e) {
    return e.what();
  }
}

int WebSession::frame_count() const { return panel_.loop_frames(); }

void WebSession::seek(int frame) {
  // Stepping back from frame 0 goes to the loop's last frame; the clock lands as the
  // desktop's does (PlanePanel::set_frame).
  panel_.set_frame(frame < 0 ? frame_count() + frame % frame_count() : frame);
}

PlaneScene WebSession::scene() const { return panel_.scene_at(panel_.frame()); }

std::string WebSession::scene_problem() const { return plane_scene_problem(scene()); }

std::string WebSession::flow_json() const {
  const PlaneScene s = scene();
  json out;
  out["frame"] = panel_.frame();
  out["frames"] = frame_count();
  out["camera"] = {{"width", s.camera.width},
                   {"height", s.camera.height},
                   {"focal_px", s.camera.focal_px},
                   {"cx", s.camera.cx},
                   {"cy", s.camera.cy}};
  json parts = json::array();
  for (int i = 0; i < kFlowPartCount; ++i) {
    const auto part = static_cast<FlowPart>(i);
    parts.push_back({{"key", flow_part_key(part)}, {"title", flow_part_title(part)}});
  }
  out["parts"] = parts;
  const std::string problem = plane_scene_problem(s);
  out["problem"] = problem;
  if (!problem.empty()) return out.dump();
  json outline = json::array();
  for (const Vec3& corner : plane_corners(s.pose)) {
    outline.push_back(point_json(centred_to_pixel(s.camera, project_centred(s.camera, corner))));
  }
  out["outline"] = outline;
  const FlowContext context = make_flow_context(s.camera, s.pose, s.motion);
  out["coefficients"] = coefficients_json(context.coefficients);
  out["planar_basis"] = planar_basis_json(to_planar_basis(context.terms));
  out["units"] = {{"tx", order_unit(0)},  {"ty", order_unit(0)},  {"j11", order_unit(1)},
                  {"j12", order_unit(1)}, {"j21", order_unit(1)}, {"j22", order_unit(1)},
                  {"px", order_unit(2)},  {"py", order_unit(2)}};
  out["motion_model"] = motion_model_name(s.motion.model);
  return out.dump();
}

std::vector<double> WebSession::flow_arrows(const std::string& part_key, double spacing_px) const {
  std::vector<double> out;
  FlowPart part = FlowPart::kFull;
  const PlaneScene s = scene();
  if (!parse_flow_part(part_key, &part) || !plane_scene_problem(s).empty()) return out;
  const FlowContext context = make_flow_context(s.camera, s.pose, s.motion);
  for (const FlowSample& sample : sample_flow_grid(context, part, std::max(1.0, spacing_px))) {
    const Vec2 p = centred_to_pixel(s.camera, sample.position);
    out.insert(out.end(), {p.x, p.y, sample.flow.x, sample.flow.y});
  }
  return out;
}

std::vector<double> WebSession::flow_streamlines(const std::string& part_key, double spacing_px,
                                                 double duration_s, int steps) const {
  std::vector<double> out;
  FlowPart part = FlowPart::kFull;
  const PlaneScene s = scene();
  if (!parse_flow_part(part_key, &part) || !plane_scene_problem(s).empty()) return out;
  const FlowContext context = make_flow_context(s.camera, s.pose, s.motion);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (const FlowSample& seed : sample_flow_grid(context, part, std::max(4.0, spacing_px))) {
    for (const Vec2& c : trace_streamline(context, part, seed.position, duration_s, steps)) {
      const Vec2 p = centred_to_pixel(s.camera, c);
      out.insert(out.end(), {p.x, p.y});
    }
    out.insert(out.end(), {nan, nan});
  }
  return out;
}

std::string WebSession::basis_json(const std::string& basis_key, double radius_px, int n) const {
  BasisKind kind = BasisKind::kPlanar;
  if (!parse_basis_kind(basis_key, &kind)) return "";
  const PlaneScene s = scene();
  const bool drawable = plane_scene_problem(s).empty();
  const TaylorTerms flow =
      drawable ? make_flow_context(s.camera, s.pose, s.motion).terms : TaylorTerms{};
  json terms = json::array();
  for (const BasisTerm& term : basis_terms(kind)) {
    json grid = json::array();
    for (int j = -n; j <= n; ++j) {
      for (int i = -n; i <= n; ++i) {
        const Vec2 p{radius_px * i / std::max(1, n), radius_px * j / std::max(1, n)};
        const Vec2 v = taylor_flow_at(term.unit, p);
        grid.insert(grid.end(), {p.x, p.y, v.x, v.y});
      }
    }
    const double value = term.coefficient(flow);
    terms.push_back({{"symbol", term.symbol},
                     {"description", term.description},
                     {"order", term.order},
                     {"unit", order_unit(term.order)},
                     {"coefficient", value},
                     {"negligible", !drawable || is_negligible(term.order, value, radius_px)},
                     {"grid", grid}});
  }
  return json{{"key", basis_key}, {"title", basis_title(kind)}, {"terms", terms}}.dump();
}

void WebSession::rebuild_comparison() {
  runs_.clear();
  comparison_problem_.clear();
  MotionScript source;
  try {
    if (state_.source.kind == "plane") {
      source = panel_.as_script();
    } else if (state_.source.kind == "script") {
      source = scripts_.at(state_.source.name);
    } else {
      comparison_problem_ = "the browser page plays planes and motion scripts; the source '" +
                            state_.source.kind +
                            "' (scenes and viewer scripts) plays in the "
                            "desktop window only";
      return;
    }
    std::vector<std::string> policies = state_.compared;
    policies.push_back(kExactPolicy);
    for (const std::string& name : policies) {
      EngineSettings settings = state_.settings;
      settings.policy = &reuse_policy(name);
      WebRun run;
      run.policy = name;
      run.animator = make_plane_animator(source, texture_, settings);
      run.last = run.animator->start();
      runs_.push_back(std::move(run));
    }
    sampled_frame_ = -1;
  } catch (const std::exception& e) {
    runs_.clear();
    comparison_problem_ = e.what();
  }
}

void WebSession::advance_runs_to(int frame) {
  if (runs_.empty()) return;
  frame = std::min(frame, runs_.front().animator->frame_count() - 1);
  if (frame == runs_.front().animator->frame()) return;
  if (frame < runs_.front().animator->frame()) {
    for (WebRun& run : runs_) {
      run.last = run.animator->start();
      run.level_frames = {};
      run.max_error_px = 0.0;
    }
  }
  while (runs_.front().animator->frame() < frame) {
    for (WebRun& run : runs_) {
      run.last = run.animator->advance();
      for (int l = 0; l < kLevelCount; ++l) run.level_frames[l] += run.last.levels[l];
      run.max_error_px = std::max(run.max_error_px, run.last.max_measured_error_px);
    }
  }
}

void WebSession::finish_runs_frame(int panel_width, int panel_height) {
  const Image& exact = runs_.back().animator->image();
  const DisplaySampling sampling =
      display_sampling(exact.width(), exact.height(), panel_width, panel_height);
  for (WebRun& run : runs_) {
    const Image& image = run.animator->image();
    flatten_into(image, sampling, kBackground, run.pixels);
    if (&run == &runs_.back()) {
      // The exact run against itself: no heat map is shown, and the figures are known.
      run.heat.clear();
      run.heat_max = 0;
      run.psnr_db = kIdenticalPsnrDb;
      continue;
    }
    difference_heat_map_into(image, exact, kHeatFullScale, sampling, run.heat);
    run.heat_max = largest_difference(image, exact);
    run.psnr_db = psnr_db(image, exact);
  }
  sampled_frame_ = runs_.front().animator->frame();
  sampled_size_ = {panel_width, panel_height};
}

int WebSession::frame_width() const {
  return runs_.empty() ? 0 : runs_.front().animator->camera().width;
}
int WebSession::frame_height() const {
  return runs_.empty() ? 0 : runs_.front().animator->camera().height;
}

std::string WebSession::update_comparison(int panel_width, int panel_height) {
  panel_width = std::clamp(panel_width, 1, kMaxPanelSide);
  panel_height = std::clamp(panel_height, 1, kMaxPanelSide);
  if (!runs_.empty()) {
    // The runs follow the clock as the desktop's run player does (player/run_player.h).
    advance_runs_to(panel_.frame() % runs_.front().animator->frame_count());
    if (sampled_frame_ != runs_.front().animator->frame() ||
        sampled_size_ != glm::ivec2(panel_width, panel_height)) {
      finish_runs_frame(panel_width, panel_height);
    }
  }
  json out;
  out["problem"] = comparison_problem_;
  out["frame"] = panel_.frame();
  out["frames"] = frame_count();
  out["width"] = frame_width();
  out["height"] = frame_height();
  out["panel"] = {panel_width, panel_height};
  out["heat_full_scale"] = kHeatFullScale;
  json runs = json::array();
  for (const WebRun& run : runs_) {
    const ReusePolicy& policy = reuse_policy(run.policy);
    json levels = json::object();
    int drawn = 0;
    for (int l = 0; l < kLevelCount; ++l) drawn += run.level_frames[l];
    for (int l = 0; l < kLevelCount; ++l) {
      levels[level_name(static_cast<Level>(l))] =
          drawn > 0 ? static_cast<double>(run.level_frames[l]) / drawn : 0.0;
    }
    json outlines = json::array();
    for (const LayerOutline& outline : run.animator->outlines()) {
      json points = json::array();
      for (const Vec2& p : outline.points) points.push_back(point_json(p));
      outlines.push_back({{"level", level_name(outline.level)}, {"points", points}});
    }
    const bool shown = !run.last.layer_reports.empty() && run.last.layer_reports[0].visible;
    runs.push_back({{"policy", run.policy},
                    {"summary", policy.summary},
                    {"level", shown ? level_name(run.last.layer_reports[0].level) : "not visible"},
                    {"measured_error_px", run.last.max_measured_error_px},
                    {"max_error_px", run.max_error_px},
                    {"level_shares", levels},
                    {"psnr_db", run.psnr_db},
                    {"heat_max", run.heat_max},
                    {"outlines", outlines}});
  }
  out["runs"] = runs;
  return out.dump();
}

std::string WebSession::lessons_json() {
  try {
    json out = json::array();
    for (const Lesson& lesson : lessons()) out.push_back(lesson_json(lesson));
    return out.dump();
  } catch (const std::exception& e) {
    return json{{"error", e.what()}}.dump();
  }
}

std::string WebSession::lesson_file_json(const std::string& text, const std::string& origin) {
  // The desktop's reader reads files: the text goes to the module's memory file system under
  // the name the user gave, and the reader's messages then name that file.
  namespace fs = std::filesystem;
  const fs::path dir = "/uploads";
  const std::string stem = fs::path(origin).filename().string();
  const fs::path path = dir / (stem.empty() ? std::string("lesson.json") : stem);
  try {
    fs::create_directories(dir);
    {
      std::ofstream out(path, std::ios::binary);
      out << text;
    }
    const Lesson lesson = read_lesson_file(path.string());
    fs::remove(path);
    add_lesson(lesson);  // played by name (go_to_lesson) from now on
    return lesson_json(lesson).dump();
  } catch (const std::exception& e) {
    std::error_code ignored;
    fs::remove(path, ignored);
    std::string message = e.what();
    const std::string shown = path.string();
    if (const auto at = message.find(shown); at != std::string::npos) {
      message.replace(at, shown.size(), origin);
    }
    return json{{"error", message}}.dump();
  }
}

std::string WebSession::script_run_json(const std::string& name) {
  try {
    const MotionScript script = read_shipped_or_file_script(name);
    const Image texture = read_image(default_texture_path());
    const std::unique_ptr<Animator> animator =
        make_plane_animator(script, texture, EngineSettings{});
    json levels = json::array();
    AnimationFrame record = animator->start();
    for (;;) {
      levels.push_back(level_name(record.layer_reports.at(0).level));
      if (animator->frame() + 1 >= animator->frame_count()) break;
      record = animator->advance();
    }
    const ScriptFrame& first = script.frames.front();
    const PlanarFlowCoefficients c =
        planar_flow_coefficients(script.camera, first.pose, first.motion);
    return json{{"levels", levels}, {"coefficients", coefficients_json(c)}}.dump();
  } catch (const std::exception& e) {
    return json{{"error", e.what()}}.dump();
  }
}

std::string WebSession::script_names_json() { return json(shipped_script_names()).dump(); }

}  // namespace oflab

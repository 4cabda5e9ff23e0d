#include "web_session.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <sstream>
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
#include "image/pixel_rows.h"
#include "lessons/claim_kinds.h"
#include "lessons/lesson_player.h"
#include "player/animation_sources.h"
#include "scene/scene_animator.h"  // SceneSettings: the exact render's near plane
#include "shown_runs.h"
#include "state/state_fields.h"
#include "state/window_state_file.h"
#include "world_json.h"

namespace oflab {
namespace {

using json = nlohmann::json;

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

WebSession::WebSession() : lab_(shipped_default_texture()) {}

std::string WebSession::state_json() const { return window_state_object(lab_.state()).dump(); }

std::string WebSession::session_file_text() const { return window_state_to_json(lab_.state()); }

std::string WebSession::run_csv_json() {
  try {
    std::ostringstream csv;
    lab_.run().write_csv(csv);
    return json{{"csv", csv.str()}}.dump();
  } catch (const std::exception& e) {
    return json{{"error", e.what()}}.dump();
  }
}

std::string WebSession::set_state(const std::string& object_json, const std::string& origin) {
  ++epoch_;  // the state may change
  try {
    const json object = json::parse(object_json);
    const std::string problem =
        lab_.apply(read_window_state_object(object, origin, "state", WindowState{}));
    return problem.empty() ? problem : origin + ": " + problem;
  } catch (const std::exception& e) {
    return e.what();
  }
}

std::string WebSession::open_session(const std::string& text, const std::string& origin) {
  ++epoch_;  // the state may change
  try {
    const std::string problem = lab_.apply(parse_session(text, origin));
    return problem.empty() ? problem : origin + ": " + problem;
  } catch (const std::exception& e) {
    return e.what();
  }
}

std::string WebSession::go_to_lesson(const std::string& name, int step) {
  ++epoch_;  // the state may change
  const Lesson* lesson = find_lesson(name);
  if (!lesson) return "unknown lesson '" + name + "' (one of " + lesson_names() + ")";
  try {
    return go_to_lesson_step(stage_, *lesson, step);
  } catch (const std::exception& e) {
    return e.what();
  }
}

std::string WebSession::check_claims_json() {
  json out = json::array();
  const WindowState& values = lab_.values();
  const Lesson* lesson = values.lesson.empty() ? nullptr : find_lesson(values.lesson);
  if (!lesson || values.lesson_step > int(lesson->steps.size())) return out.dump();
  const int step = values.lesson_step;
  const std::vector<LessonClaim>& claims =
      step == 0 ? lesson->claims : lesson->steps[std::size_t(step) - 1].claims;
  const auto bound = [](double v, double open) { return v == open ? json() : json(v); };
  for (const LessonClaim& claim : claims) {
    const ClaimKind* kind = find_claim_kind(claim.claim);
    const bool engine = kind && kind->source == ClaimSource::kEngine;
    json item = {{"says", claim.says},
                 {"kind", claim.claim},
                 {"source", engine ? "engine" : "screen"},
                 {"at_least", bound(claim.at_least, -1e300)},
                 {"at_most", bound(claim.at_most, 1e300)}};
    // One screen kind the page measures itself (page_panel_fill); the others are the desktop's.
    const double measured = engine                        ? measure_engine_claim(lab_, claim)
                            : claim.claim == "panel_fill" ? page_panel_fill()
                                                          : std::nan("");
    if (engine || !std::isnan(measured)) {
      const bool holds = measured >= claim.at_least && measured <= claim.at_most;
      item["measured"] = std::isnan(measured) ? json() : json(measured);
      item["holds"] = holds;
      item["line"] = describe(*lesson, ClaimCheck{step, claim, measured, holds});
    }
    out.push_back(item);
  }
  return out.dump();
}

std::string WebSession::state_schema_json() { return state_schema().dump(); }

std::string WebSession::add_script(const std::string& text, const std::string& origin) {
  // The lab reads scripts by name or path: the text goes to the module's memory file system,
  // under the name the user gave.
  namespace fs = std::filesystem;
  try {
    parse_script(text, origin);  // refused before it is kept
    const fs::path dir = "/uploads/scripts";
    fs::create_directories(dir);
    std::string stem = fs::path(origin).filename().string();
    if (stem.empty()) stem = "script.json";
    const fs::path path = dir / stem;
    std::ofstream(path, std::ios::binary) << text;
    return json{{"path", path.string()}}.dump();
  } catch (const std::exception& e) {
    return json{{"error", e.what()}}.dump();
  }
}

int WebSession::frame_count() const { return lab_.panel().loop_frames(); }

void WebSession::seek(int frame) {
  // Stepping back from frame 0 goes to the loop's last frame; the clock lands as the
  // desktop's does (PlanePanel::set_frame).
  lab_.panel().set_frame(frame < 0 ? frame_count() + frame % frame_count() : frame);
}

PlaneScene WebSession::scene() const { return lab_.panel().scene_at(lab_.panel().frame()); }

std::string WebSession::scene_problem() const { return plane_scene_problem(scene()); }

std::string WebSession::flow_json() const {
  const PlaneScene s = scene();
  json out;
  out["frame"] = frame();
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

const PlaneImage& WebSession::exact_plane_image() {
  return plane_image_.image(scene(), lab_.panel().texture(), lab_.run().settings().sampling, epoch_,
                            frame());
}

const PlaneWorldLoop& WebSession::world_loop() {
  if (world_epoch_ != epoch_) {
    world_loop_ = panel_world_loop(lab_.panel());
    world_epoch_ = epoch_;
  }
  return world_loop_;
}

// The animator of a scene source (its kind walks a viewer through a scene), or nullptr.
const Animator* WebSession::scene_animator() {
  if (!lab_.run().source_kind().uses_viewer) return nullptr;
  return lab_.run().animator();
}

std::string WebSession::world_loop_json() {
  if (const Animator* animator = scene_animator()) {
    if (scene_world_epoch_ != epoch_) {
      scene_world_loop_ = scene_world_loop(*animator, PlanePanel::kSecondsPerFrame);
      scene_world_epoch_ = epoch_;
    }
    return oflab::scene_world_loop_json(scene_world_loop_);
  }
  return oflab::world_loop_json(world_loop(), lab_.panel().texture_source());
}

std::string WebSession::world_frame_json() {
  if (const Animator* animator = scene_animator()) {
    if (scene_world_epoch_ != epoch_) world_loop_json();
    return oflab::scene_world_frame_json(scene_world_loop_, *animator,
                                         PlanePanel::kSecondsPerFrame);
  }
  return oflab::world_frame_json(world_loop(), lab_.panel());
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

namespace {

// What the exact run depends on: the plane, its script and texture, the source and the
// engine settings of the state (not its view, frame or display options).
std::string exact_run_key(const WindowState& state) {
  json object = window_state_object(state);
  json key = {{"plane", object["plane"]},
              {"script", object.value("script", json())},
              {"texture", object.value("texture", json())},
              {"animation", object["animation"]}};
  for (const char* field : {"display", "exact_renderer", "framing", "zoom", "compared"}) {
    key["animation"].erase(field);
  }
  return key.dump();
}

}  // namespace

std::string WebSession::comparison_problem() {
  shown_animators();
  return comparison_problem_;
}

std::vector<const Animator*> WebSession::shown_animators() {
  // The page asks several times a frame (the problem, the count, the size, the update):
  // the engines are found once per frame and state.
  if (memo_epoch_ == epoch_ && memo_frame_ == frame()) return memo_;
  memo_ = find_shown_animators();
  memo_epoch_ = epoch_;
  memo_frame_ = frame();
  return memo_;
}

std::vector<const Animator*> WebSession::find_shown_animators() {
  comparison_problem_.clear();
  std::vector<const Animator*> animators;
  const std::vector<ShownRun> shown = shown_runs(lab_, &comparison_problem_);
  for (const ShownRun& run : shown) animators.push_back(run.animator);
  if (animators.empty()) return animators;
  // A compared `rerender` run is the exact projection itself (the same source and settings
  // but the policy): it is shown as the exact panel too, and no third engine runs.
  const auto rerender = std::find_if(
      shown.begin(), shown.end(), [](const ShownRun& run) { return run.policy == kExactPolicy; });
  if (rerender != shown.end()) {
    exact_.reset();
    exact_key_.clear();
    exact_shown_ = rerender->animator;
    exact_record_ = rerender->last;
    animators.push_back(exact_shown_);
    return animators;
  }
  try {
    if (exact_run_key(lab_.state()) != exact_key_) rebuild_exact();
    advance_exact_to(animators.front()->frame());
  } catch (const std::exception& e) {
    exact_.reset();
    exact_key_.clear();
    comparison_problem_ = e.what();
    return {};
  }
  exact_shown_ = exact_.get();
  exact_record_ = &exact_last_;
  animators.push_back(exact_shown_);
  return animators;
}

void WebSession::rebuild_exact() {
  exact_.reset();
  exact_key_ = exact_run_key(lab_.state());
  SourceChoice choice = lab_.run().source();
  // Scene shifting's exact projection is the scene's: every polygon rendered exactly.
  if (choice.kind == "scene-shifting") choice.kind = "scene";
  const AnimationSourceKind* kind = find_animation_source_kind(choice.kind);
  if (!kind) throw std::invalid_argument("unknown source kind '" + choice.kind + "'");
  EngineSettings settings = lab_.run().settings();
  settings.policy = &reuse_policy(kExactPolicy);
  exact_ = kind->make(choice, lab_.panel(), settings);
  exact_last_ = exact_->start();
  sampled_frame_ = -1;
}

void WebSession::advance_exact_to(int frame) {
  frame = std::min(frame, exact_->frame_count() - 1);
  if (frame < exact_->frame()) exact_last_ = exact_->start();
  while (exact_->frame() < frame) exact_last_ = exact_->advance();
}

std::string WebSession::analysis_json(int frames) { return analysis_history_json(lab_, frames); }

int WebSession::run_count() { return int(shown_animators().size()); }

int WebSession::frame_width() {
  const std::vector<const Animator*> animators = shown_animators();
  return animators.empty() ? 0 : animators.back()->camera().width;
}

int WebSession::frame_height() {
  const std::vector<const Animator*> animators = shown_animators();
  return animators.empty() ? 0 : animators.back()->camera().height;
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

std::string WebSession::scene_names_json() {
  return json{{"scenes", shipped_names("scenes")}, {"viewers", shipped_names("viewer-scripts")}}
      .dump();
}

}  // namespace oflab

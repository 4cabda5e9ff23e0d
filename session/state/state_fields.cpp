#include "state/state_fields.h"

#include <algorithm>
#include <cmath>
#include <set>

#include "engine/reuse_policy.h"
#include "flow/limits.h"
#include "state/window_state_file.h"

namespace oflab {
namespace {

using namespace json_fields;
using Where = Place<SessionError>;
using Get = std::function<json(const WindowState&)>;

json vec(const Vec3& v) { return json::array({v.x, v.y, v.z}); }
json vec(const Vec2& v) { return json::array({v.x, v.y}); }

bool boolean_value(const json& value, const Where& w, const std::string& key) {
  if (!value.is_boolean()) w.fail(key, "must be true or false");
  return value.get<bool>();
}

std::string text_value(const json& value, const Where& w, const std::string& key) {
  if (!value.is_string()) w.fail(key, "must be a string");
  return value.get<std::string>();
}

// A whole number (its range is checked with the rest: window_state_problem).
int whole_value(const json& value, const Where& w, const std::string& key) {
  const double v = number(value, w, key);
  if (v != std::floor(v)) w.fail(key, "must be a whole number");
  return int(v);
}

// A field whose value is a member reached by `at` and read by `read`.
template <class T, class At, class Read>
StateField field(std::string path, std::string type, std::string range, std::string doc, At at,
                 Read read, std::function<json(const T&)> write) {
  StateField f{std::move(path), std::move(type), std::move(range),
               std::move(doc),  nullptr,         nullptr};
  f.get = [at, write](const WindowState& s) { return write(*at(const_cast<WindowState*>(&s))); };
  f.set = [at, read](const json& value, const Where& w, const std::string& key, WindowState* s) {
    *at(s) = read(value, w, key);
  };
  return f;
}

template <class At>
StateField flag(std::string path, std::string doc, At at) {
  return field<bool>(std::move(path), "true or false", "", std::move(doc), at, boolean_value,
                     [](const bool& b) { return json(b); });
}

template <class At>
StateField text_field(std::string path, std::string range, std::string doc, At at) {
  return field<std::string>(std::move(path), "text", std::move(range), std::move(doc), at,
                            text_value, [](const std::string& t) { return json(t); });
}

template <class At>
StateField whole_field(std::string path, const Limit& limit, std::string doc, At at) {
  return field<int>(std::move(path), "whole number", limit.range_text(), std::move(doc), at,
                    whole_value, [](const int& v) { return json(v); });
}

template <class At>
StateField number_field(std::string path, std::string range, std::string doc, At at) {
  return field<double>(std::move(path), "number", std::move(range), std::move(doc), at,
                       number<SessionError>, [](const double& v) { return json(v); });
}

template <class At>
StateField vec3_field(std::string path, std::string range, std::string doc, At at) {
  return field<Vec3>(std::move(path), "[x, y, z]", std::move(range), std::move(doc), at,
                     vec3_value<SessionError>, [](const Vec3& v) { return vec(v); });
}

// A name of a table, parsed by `parse` (false for an unknown name) and printed by `name`.
template <class T, class At>
StateField named(std::string path, std::string names, std::string doc, At at,
                 bool (*parse)(const std::string&, T*), std::function<std::string(T)> name) {
  const std::string range = "one of " + names;
  return field<T>(
      std::move(path), "name", range, std::move(doc), at,
      [parse, range](const json& value, const Where& w, const std::string& key) {
        T out{};
        if (!parse(text_value(value, w, key), &out)) w.fail(key, range);
        return out;
      },
      [name](const T& v) { return json(name(v)); });
}

bool parse_flow_part_key(const std::string& key, FlowPart* part) {
  return parse_flow_part(key, part);
}
bool parse_basis(const std::string& key, BasisKind* kind) { return parse_basis_kind(key, kind); }
bool parse_motion(const std::string& key, MotionModel* model) {
  return parse_motion_model(key.c_str(), model);
}
bool parse_policy(const std::string& key, const ReusePolicy** policy) {
  *policy = find_reuse_policy(key);
  return *policy != nullptr;
}
bool parse_budget_unit(const std::string& key, FrameBudget::Unit* unit) {
  const std::pair<const char*, FrameBudget::Unit> units[] = {
      {"none", FrameBudget::Unit::kNone},
      {"pixels", FrameBudget::Unit::kPixels},
      {"ms", FrameBudget::Unit::kMilliseconds}};
  for (const auto& [name, value] : units) {
    if (key == name) {
      *unit = value;
      return true;
    }
  }
  return false;
}
std::string budget_unit_name(FrameBudget::Unit unit) {
  return unit == FrameBudget::Unit::kPixels         ? "pixels"
         : unit == FrameBudget::Unit::kMilliseconds ? "ms"
                                                    : "none";
}

std::string flow_part_names() {
  std::string names;
  for (int k = 0;; ++k) {
    const FlowPart part = FlowPart(k);
    FlowPart parsed;
    if (!parse_flow_part(flow_part_key(part), &parsed) || parsed != part) break;
    names += (names.empty() ? "" : ", ") + std::string(flow_part_key(part));
  }
  return names;
}

std::string vec_range(const Limit& limit) { return "each " + limit.range_text(); }

void add_top_fields(std::vector<StateField>& f) {
  using S = WindowState;
  f.push_back(text_field("view", "a view of the window's view table",
                         "the view in front, by its command-line name",
                         [](S* s) { return &s->view; }));
  f.push_back(
      whole_field("frame", limits::kFrameCount, "the frame shown", [](S* s) { return &s->frame; }));
  f.push_back(flag("playing", "the motion plays", [](S* s) { return &s->playing; }));
  f.push_back(whole_field("play_rate", limits::kPlayRate, "live play, frames per second",
                          [](S* s) { return &s->play_rate; }));
  f.push_back(flag("presentation", "large text and thick lines for a projector",
                   [](S* s) { return &s->presentation; }));
  f.push_back(
      flag("scene_panel", "the scene panel is shown", [](S* s) { return &s->scene_panel; }));
  f.push_back(flag("cause_and_effect", "the world view beside the flow view instead of tabs",
                   [](S* s) { return &s->cause_and_effect; }));
  f.push_back(named<WorldCamera>(
      "world_camera", "orbit, eye",
      "where the world view looks from: beside the eye (orbit) or through it (eye)",
      [](S* s) { return &s->world_camera; }, parse_world_camera,
      [](WorldCamera c) { return std::string(world_camera_name(c)); }));
  f.push_back(text_field("lesson", "a lesson's name, or empty", "the lesson whose caption shows",
                         [](S* s) { return &s->lesson; }));
  f.push_back(whole_field("lesson_step", Limit{"lesson step", "", 0, 1000, true},
                          "the lesson's step on screen (0: its narrative)",
                          [](S* s) { return &s->lesson_step; }));
  f.push_back(text_field("study.open", "a shipped study's name, or empty",
                         "the study window, open on this study's set-up page (empty: closed)",
                         [](S* s) { return &s->study_open; }));
  f.push_back(flag("study.use_threshold",
                   "the reuse thresholds become the study window's measured threshold",
                   [](S* s) { return &s->study_use_threshold; }));
}

void add_flow_fields(std::vector<StateField>& f) {
  using S = WindowState;
  f.push_back(named<FlowPart>(
      "flow.part", flow_part_names(), "the part of the flow the flow view draws",
      [](S* s) { return &s->flow.part; }, parse_flow_part_key,
      [](FlowPart p) { return std::string(flow_part_key(p)); }));
  f.push_back(number_field("flow.spacing_px", "0 (automatic) or 4..1000 px",
                           "the flow view's grid spacing",
                           [](S* s) { return &s->flow.spacing_px; }));
  for (const FlowDrawOption& option : flow_draw_options()) {
    bool FlowDisplay::*member = option.member;
    f.push_back(flag(std::string("flow.") + option.key, option.tooltip,
                     [member](S* s) { return &(s->flow.*member); }));
  }
}

void add_basis_fields(std::vector<StateField>& f) {
  using S = WindowState;
  f.push_back(named<BasisKind>(
      "basis.kind", "taylor, waxman-ullman, planar", "the basis of the basis view",
      [](S* s) { return &s->basis; }, parse_basis,
      [](BasisKind k) { return std::string(basis_key(k)); }));
  f.push_back(flag("basis.playing", "the gallery animates its deformation amount",
                   [](S* s) { return &s->basis_playing; }));
  f.push_back(flag("basis.explorer", "the basis view shows the explorer",
                   [](S* s) { return &s->basis_explorer; }));
  for (size_t k = 0; k < explorer_terms().size(); ++k) {
    const ExplorerTerm& term = explorer_terms()[k];
    f.push_back(number_field(std::string("basis.terms.") + term.key, term.limit->range_text(),
                             std::string("the explorer's ") + term.description,
                             [k](S* s) { return &s->explorer_terms[k]; }));
  }
}

// The camera of the scene panel.
void add_camera_fields(std::vector<StateField>& f) {
  using S = WindowState;
  using namespace limits;
  // The camera's principal point follows its size (make_camera), so each of the three is
  // set through make_camera.
  const auto camera = [](std::string path, const Limit& limit, std::string doc, auto member,
                         bool whole) {
    StateField c{std::move(path),
                 whole ? "whole number" : "number",
                 limit.range_text(),
                 std::move(doc),
                 nullptr,
                 nullptr};
    c.get = [member](const S& s) { return json(s.plane.camera.*member); };
    c.set = [member, whole](const json& value, const Where& w, const std::string& key, S* s) {
      Camera cam = s->plane.camera;
      cam.*member = whole ? whole_value(value, w, key) : number(value, w, key);
      s->plane.camera = make_camera(cam.focal_px, int(cam.width), int(cam.height));
    };
    return c;
  };
  f.push_back(camera("plane.camera.focal_px", kFocalLength, "the camera's focal length",
                     &Camera::focal_px, false));
  f.push_back(camera("plane.camera.width", kImageSize, "the image width", &Camera::width, true));
  f.push_back(camera("plane.camera.height", kImageSize, "the image height", &Camera::height, true));
}

void add_plane_fields(std::vector<StateField>& f) {
  using S = WindowState;
  using namespace limits;
  f.push_back(vec3_field("plane.pose.point", "z " + kDistance.range_text(),
                         "the plane's centre at frame 0, camera frame (u)",
                         [](S* s) { return &s->plane.pose.point; }));
  f.push_back(vec3_field("plane.pose.normal", "not zero", "the plane's normal",
                         [](S* s) { return &s->plane.pose.normal; }));
  f.push_back(vec3_field("plane.pose.up", "not along the normal", "the texture's up direction",
                         [](S* s) { return &s->plane.pose.up; }));
  f.push_back(field<Vec2>(
      "plane.pose.size", "[x, y]", vec_range(kPlaneSize), "the plane's width and height",
      [](S* s) { return &s->plane.pose.size; }, vec2_value<SessionError>,
      [](const Vec2& v) { return vec(v); }));
  f.push_back(field<glm::ivec2>(
      "plane.pose.texture_size", "[x, y]", "each 1..16384 texels, whole",
      "the texture's size in texels", [](S* s) { return &s->plane.pose.texture_size; },
      [](const json& value, const Where& w, const std::string& key) {
        const Vec2 t = vec2_value(value, w, key);
        if (t.x < 1 || t.y < 1 || t.x > 16384 || t.y > 16384 || t.x != std::floor(t.x) ||
            t.y != std::floor(t.y)) {
          w.fail(key, "must be two whole numbers from 1 to 16384");
        }
        return glm::ivec2(int(t.x), int(t.y));
      },
      [](const glm::ivec2& t) {
        return json::array({t.x, t.y});
      }));
  f.push_back(vec3_field("plane.motion.velocity", vec_range(kVelocity), "the plane's velocity V",
                         [](S* s) { return &s->plane.motion.velocity; }));
  f.push_back(vec3_field("plane.motion.omega", vec_range(kAngularVelocity),
                         "the plane's angular velocity Omega",
                         [](S* s) { return &s->plane.motion.omega; }));
  f.push_back(named<MotionModel>(
      "plane.motion.model", motion_model_name_list(), "how V and Omega move the plane",
      [](S* s) { return &s->plane.motion.model; }, parse_motion,
      [](MotionModel m) { return std::string(motion_model_name(m)); }));
  f.push_back(text_field("script", "a shipped script's name or a file, or empty",
                         "the motion script the scene panel plays",
                         [](S* s) { return &s->script; }));
  f.push_back(text_field("texture",
                         "an image file or a shipped texture's name, or empty for the butterfly",
                         "the plane's texture", [](S* s) { return &s->texture; }));
}

// What of each scene layer the warps compute (EngineSettings::warp_area).
void add_warp_area_field(std::vector<StateField>& f) {
  using S = WindowState;
  f.push_back(named<WarpArea>(
      "animation.warp", warp_area_name_list(), "what of each scene layer is warped",
      [](S* s) { return &s->settings.warp_area; }, parse_warp_area,
      [](WarpArea v) { return std::string(warp_area_name(v)); }));
}

void add_engine_fields(std::vector<StateField>& f) {
  using S = WindowState;
  using namespace limits;
  f.push_back(text_field("animation.source.kind", "a source kind of the window",
                         "what the animation view plays", [](S* s) { return &s->source.kind; }));
  f.push_back(text_field("animation.source.name", "a shipped name or a file",
                         "the script or scene it plays", [](S* s) { return &s->source.name; }));
  f.push_back(text_field("animation.source.viewer", "a shipped viewer script or a file",
                         "the viewer script walking the scene",
                         [](S* s) { return &s->source.viewer; }));
  f.push_back(named<const ReusePolicy*>(
      "animation.mode", reuse_policy_names(), "the engine's reuse policy",
      [](S* s) { return &s->settings.policy; }, parse_policy,
      [](const ReusePolicy* p) { return p->name; }));
  f.push_back(field<TermArray>(
      "animation.thresholds", "list of 4 numbers", "each " + kThreshold.range_text(),
      "the error thresholds of none, translation, affine, perspective",
      [](S* s) { return &s->settings.thresholds; },
      [](const json& value, const Where& w, const std::string& key) {
        if (!value.is_array() || value.size() != size_t(kTermCount)) {
          w.fail(key, "must be a list of " + std::to_string(kTermCount) + " numbers");
        }
        TermArray t{};
        for (size_t k = 0; k < t.size(); ++k) t[k] = number(value[k], w, key);
        return t;
      },
      [](const TermArray& t) { return json(std::vector<double>(t.begin(), t.end())); }));
  f.push_back(named<DeltaPolicy>(
      "animation.delta", delta_policy_name_list(), "the Delta policy",
      [](S* s) { return &s->settings.delta; }, parse_delta_policy,
      [](DeltaPolicy d) { return std::string(delta_policy_name(d)); }));
  f.push_back(named<Sampling>(
      "animation.sampling", sampling_name_list(), "the warps' sampling",
      [](S* s) { return &s->settings.sampling; }, parse_sampling,
      [](Sampling v) { return std::string(sampling_name(v)); }));
  add_warp_area_field(f);
  f.push_back(named<ContentKind>(
      "animation.content", content_name_list(), "what a re-render draws",
      [](S* s) { return &s->settings.content.kind; }, parse_content,
      [](ContentKind k) { return std::string(content_name(k)); }));
  f.push_back(whole_field("animation.content_quality", kContentQuality,
                          "samples per pixel of a lit content",
                          [](S* s) { return &s->settings.content.quality; }));
  f.push_back(named<FrameBudget::Unit>(
      "animation.budget.unit", "none, pixels, ms", "the budget policy's frame budget unit",
      [](S* s) { return &s->settings.budget.unit; }, parse_budget_unit, budget_unit_name));
  f.push_back(number_field("animation.budget.amount",
                           kBudgetPixels.range_text() + " or " + kBudgetMs.range_text(),
                           "the frame budget", [](S* s) { return &s->settings.budget.amount; }));
  f.push_back(whole_field("animation.cadence", kCadence, "a fixed cadence's period",
                          [](S* s) { return &s->settings.cadence; }));
  f.push_back(flag("animation.stabilization.automatic", "the stabilization plane is automatic",
                   [](S* s) { return &s->settings.stabilization.automatic; }));
  f.push_back(vec3_field("animation.stabilization.point", vec_range(kStabilizationPlane),
                         "a point of the stabilization plane",
                         [](S* s) { return &s->settings.stabilization.point; }));
  f.push_back(vec3_field("animation.stabilization.normal", vec_range(kStabilizationPlane),
                         "the stabilization plane's normal, not zero",
                         [](S* s) { return &s->settings.stabilization.normal; }));
}

void add_view_fields(std::vector<StateField>& f) {
  using S = WindowState;
  f.push_back(named<PanelDisplay>(
      "animation.display", panel_display_names(), "the animation view's layout",
      [](S* s) { return &s->display; }, parse_panel_display,
      [](PanelDisplay d) { return std::string(panel_display_name(d)); }));
  f.push_back(field<std::vector<std::string>>(
      "animation.compared", "list of names",
      "1.." + std::to_string(kMaxComparedPolicies) + " distinct reuse policies",
      "the policies the comparison layout plays, in panel order", [](S* s) { return &s->compared; },
      [](const json& value, const Where& w, const std::string& key) {
        if (!value.is_array()) w.fail(key, "must be a list of policy names");
        std::vector<std::string> names;
        for (const json& name : value) {
          if (!name.is_string()) w.fail(key, "must be a list of policy names");
          names.push_back(name.get<std::string>());
        }
        return names;
      },
      [](const std::vector<std::string>& names) { return json(names); }));
  f.push_back(text_field("animation.exact_renderer", "core, vtk", "who draws the exact panel",
                         [](S* s) { return &s->exact_renderer; }));
  f.push_back(named<PanelFraming>(
      "animation.framing", panel_framing_names(),
      "what every panel frames: the whole loop, what is drawn now, or auto (what is drawn in "
      "presentation mode, else the loop)",
      [](S* s) { return &s->framing; }, parse_panel_framing,
      [](PanelFraming f) { return std::string(panel_framing_name(f)); }));
  f.push_back(number_field("animation.zoom", limits::kZoom.range_text(),
                           "zoom on top of the framing", [](S* s) { return &s->zoom; }));
}

std::vector<StateField> make_fields() {
  std::vector<StateField> f;
  add_top_fields(f);
  add_flow_fields(f);
  add_basis_fields(f);
  add_camera_fields(f);
  add_plane_fields(f);
  add_engine_fields(f);
  add_view_fields(f);
  return f;
}

// The members an object at `prefix` ("" or "plane.pose.") may have, in table order.
std::vector<std::string> members_at(const std::string& prefix) {
  std::vector<std::string> names;
  for (const StateField& field : state_fields()) {
    if (field.path.compare(0, prefix.size(), prefix) != 0) continue;
    const std::string rest = field.path.substr(prefix.size());
    const std::string name = rest.substr(0, rest.find('.'));
    if (std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
  }
  return names;
}

void read_object(const json& object, const std::string& origin, const std::string& part,
                 const std::string& prefix, WindowState* state) {
  const Where w{origin, prefix.empty() ? part : prefix.substr(0, prefix.size() - 1)};
  only_fields(object, w, members_at(prefix));
  for (auto it = object.begin(); it != object.end(); ++it) {
    const std::string path = prefix + it.key();
    if (const StateField* leaf = find_state_field(path)) {
      leaf->set(it.value(), w, it.key(), state);
    } else {
      if (!it.value().is_object()) w.fail(it.key(), "must be an object");
      read_object(it.value(), origin, part, path + ".", state);
    }
  }
}

std::string cell(std::string text) {
  for (size_t at = text.find('|'); at != std::string::npos; at = text.find('|', at + 2)) {
    text.replace(at, 1, "\\|");
  }
  return text;
}

}  // namespace

const std::vector<StateField>& state_fields() {
  static const std::vector<StateField> fields = make_fields();
  return fields;
}

const StateField* find_state_field(const std::string& path) {
  for (const StateField& field : state_fields()) {
    if (field.path == path) return &field;
  }
  return nullptr;
}

json state_fields_object(const WindowState& state) {
  json object = json::object();
  for (const StateField& field : state_fields()) {
    object[json::json_pointer("/" + [&] {
      std::string pointer = field.path;
      std::replace(pointer.begin(), pointer.end(), '.', '/');
      return pointer;
    }())] = field.get(state);
  }
  return object;
}

void read_state_fields(const json& object, const std::string& origin, const std::string& part,
                       WindowState* state) {
  read_object(object, origin, part, "", state);
}

bool same_fields(const WindowState& a, const WindowState& b) {
  for (const StateField& field : state_fields()) {
    if (field.get(a) != field.get(b)) return false;
  }
  return true;
}

json state_schema() {
  const WindowState defaults;
  json schema = json::array();
  for (const StateField& field : state_fields()) {
    schema.push_back({{"name", field.path},
                      {"type", field.type},
                      {"range", field.range},
                      {"default", field.get(defaults)},
                      {"doc", field.doc}});
  }
  return schema;
}

std::string state_fields_markdown() {
  const WindowState defaults;
  std::string table = "| field | type | range | default | meaning |\n|---|---|---|---|---|\n";
  for (const StateField& field : state_fields()) {
    table += "| `" + field.path + "` | " + cell(field.type) + " | " +
             cell(field.range.empty() ? "-" : field.range) + " | `" +
             cell(field.get(defaults).dump()) + "` | " + cell(field.doc) + " |\n";
  }
  return table;
}

}  // namespace oflab

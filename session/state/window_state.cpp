#include "state/window_state.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <utility>

#include "engine/reuse_policy.h"
#include "flow/limits.h"
#include "formats/datasets.h"
#include "state/state_fields.h"

namespace oflab {
namespace {

const std::pair<PanelFraming, const char*> kFramings[] = {{PanelFraming::kAuto, "auto"},
                                                          {PanelFraming::kLoop, "loop"},
                                                          {PanelFraming::kContent, "content"}};

constexpr PanelDisplay kDisplays[] = {PanelDisplay::kSideBySide, PanelDisplay::kDifference,
                                      PanelDisplay::kBlink, PanelDisplay::kComparison};

// "field: what problem" when `limit` refuses `value`, else "".
std::string check(const char* field, const Limit& limit, double value) {
  const std::string problem = limit.problem(value);
  return problem.empty() ? problem : std::string(field) + ": " + limit.what + " " + problem;
}

// The first non-empty phrase of `problems`, or "".
std::string first_of(std::initializer_list<std::string> problems) {
  for (const std::string& p : problems) {
    if (!p.empty()) return p;
  }
  return "";
}

std::string check_each(const char* field, const Limit& limit, const Vec3& v) {
  return first_of({check(field, limit, v.x), check(field, limit, v.y), check(field, limit, v.z)});
}

// "" when `name` is empty or a shipped study's (datasets/studies/NAME.json).
std::string study_problem(const std::string& name) {
  if (name.empty()) return "";
  const std::vector<std::string> studies = shipped_names("studies");
  if (std::find(studies.begin(), studies.end(), name) != studies.end()) return "";
  return "study.open: unknown study '" + name + "' (one of " + joined_names(studies) + ")";
}

}  // namespace

std::string plane_state_problem(const PlaneScene& p) {
  using namespace limits;
  const std::string limits_problem = first_of({
      check("plane.camera.focal_px", kFocalLength, p.camera.focal_px),
      check("plane.camera.width", kImageSize, p.camera.width),
      check("plane.camera.height", kImageSize, p.camera.height),
      check("plane.pose.point", kDistance, p.pose.point.z),
      check("plane.pose.size", kPlaneSize, p.pose.size.x),
      check("plane.pose.size", kPlaneSize, p.pose.size.y),
      check_each("plane.motion.velocity", kVelocity, p.motion.velocity),
      check_each("plane.motion.omega", kAngularVelocity, p.motion.omega),
  });
  if (!limits_problem.empty()) return limits_problem;
  // Within every limit, the plane may still not be drawable (seen edge on, through the eye).
  const std::string drawable = plane_scene_problem(p);
  return drawable.empty() ? drawable : "plane: " + drawable;
}

std::string settings_state_problem(const EngineSettings& s) {
  using namespace limits;
  for (double t : s.thresholds) {
    const std::string p = check("animation.thresholds", kThreshold, t);
    if (!p.empty()) return p;
  }
  const std::string cadence = check("animation.cadence", kCadence, s.cadence);
  if (!cadence.empty()) return cadence;
  if (!s.stabilization.automatic) {
    const std::string plane = first_of(
        {check_each("animation.stabilization.point", kStabilizationPlane, s.stabilization.point),
         check_each("animation.stabilization.normal", kStabilizationPlane,
                    s.stabilization.normal)});
    if (!plane.empty()) return plane;
    if (glm::length(s.stabilization.normal) == 0.0) {
      return "animation.stabilization.normal: must not be zero";
    }
  }
  if (s.budget.unit == FrameBudget::Unit::kPixels) {
    return check("animation.budget_pixels", kBudgetPixels, s.budget.amount);
  }
  if (s.budget.unit == FrameBudget::Unit::kMilliseconds) {
    return check("animation.budget_ms", kBudgetMs, s.budget.amount);
  }
  return check("animation.content_quality", kContentQuality, s.content.quality);
}

namespace {

std::string compared_problem(const std::vector<std::string>& compared) {
  if (compared.empty() || int(compared.size()) > kMaxComparedPolicies) {
    return "animation.compared: " + std::to_string(compared.size()) + " policies; give 1.." +
           std::to_string(kMaxComparedPolicies);
  }
  for (size_t i = 0; i < compared.size(); ++i) {
    if (!find_reuse_policy(compared[i])) {
      return "animation.compared: unknown policy '" + compared[i] + "' (one of " +
             reuse_policy_names() + ")";
    }
    if (std::find(compared.begin(), compared.begin() + long(i), compared[i]) !=
        compared.begin() + long(i)) {
      return "animation.compared: '" + compared[i] + "' is named twice";
    }
  }
  return "";
}

// A given stabilization plane where the eye is at the origin (the plane source: the viewer
// frame of frame 0): it must not pass within limits::kDistance's least distance of the eye,
// and must meet the optical axis in front of it (Z > 0) unless it is parallel to the axis.
// Scenes give it in world coordinates, where the eye is the viewer script's, so only the
// plane source is checked here.
std::string stabilization_problem(const WindowState& s) {
  const StabilizationPlane& plane = s.settings.stabilization;
  if (plane.automatic || s.source.kind != "plane" || glm::length(plane.normal) == 0.0) return "";
  const Vec3 n = glm::normalize(plane.normal);
  const double distance = glm::dot(n, plane.point);  // signed distance from the eye, u
  std::ostringstream text;
  if (std::abs(distance) < limits::kDistance.minimum) {
    text << "animation.stabilization: the plane passes " << std::abs(distance)
         << " u from the eye; it must pass at least " << limits::kDistance.minimum
         << " u away (the least distance of a plane)";
  } else if (n.z != 0.0 && distance / n.z < 0.0) {
    text << "animation.stabilization: the plane meets the optical axis behind the eye, at Z = "
         << distance / n.z << " u; it must be in front (Z > 0)";
  }
  return text.str();
}

}  // namespace

std::string panel_display_names(const std::string& separator) {
  std::string names;
  for (PanelDisplay d : kDisplays)
    names += (names.empty() ? "" : separator) + panel_display_name(d);
  return names;
}

const char* panel_display_name(PanelDisplay display) {
  switch (display) {
    case PanelDisplay::kDifference:
      return "difference";
    case PanelDisplay::kBlink:
      return "blink";
    case PanelDisplay::kComparison:
      return "comparison";
    default:
      return "side-by-side";
  }
}

bool parse_panel_display(const std::string& text, PanelDisplay* display) {
  for (PanelDisplay d : kDisplays) {
    if (text == panel_display_name(d)) {
      *display = d;
      return true;
    }
  }
  return false;
}

const char* world_camera_name(WorldCamera camera) {
  return camera == WorldCamera::kEye ? "eye" : "orbit";
}

bool parse_world_camera(const std::string& text, WorldCamera* camera) {
  for (WorldCamera c : {WorldCamera::kOrbit, WorldCamera::kEye}) {
    if (text == world_camera_name(c)) {
      *camera = c;
      return true;
    }
  }
  return false;
}

const char* panel_framing_name(PanelFraming framing) {
  for (const auto& [f, name] : kFramings) {
    if (f == framing) return name;
  }
  return "auto";
}

bool parse_panel_framing(const std::string& text, PanelFraming* framing) {
  for (const auto& [f, name] : kFramings) {
    if (text == name) {
      *framing = f;
      return true;
    }
  }
  return false;
}

std::string panel_framing_names(const std::string& separator) {
  std::string names;
  for (const auto& entry : kFramings) names += (names.empty() ? "" : separator) + entry.second;
  return names;
}

bool operator==(const WindowState& a, const WindowState& b) { return same_fields(a, b); }

std::string window_state_problem(const WindowState& s) {
  using namespace limits;
  if (!s.settings.policy) return "animation.mode: no reuse policy";
  if (!(s.flow.spacing_px == 0.0 || (s.flow.spacing_px >= 4.0 && s.flow.spacing_px <= 1000.0))) {
    return "flow.spacing_px: must be 0 (automatic) or 4..1000 px";
  }
  return first_of({plane_state_problem(s.plane), settings_state_problem(s.settings),
                   stabilization_problem(s), explorer_terms_problem(s.explorer_terms),
                   compared_problem(s.compared), check("animation.zoom", kZoom, s.zoom),
                   check("play_rate", kPlayRate, s.play_rate), check("frame", kFrameCount, s.frame),
                   s.lesson_step >= 0 && (s.lesson_step == 0 || !s.lesson.empty())
                       ? ""
                       : "lesson_step: must be 0 without a lesson, and not negative",
                   study_problem(s.study_open)});
}

}  // namespace oflab

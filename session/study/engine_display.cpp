#include "study/engine_display.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <mutex>
#include <tuple>

#include "engine/engine.h"
#include "engine/script.h"
#include "image/layer.h"

namespace oflab {
namespace {

constexpr double kPi = 3.14159265358979323846;

// The clip's camera and plane: a 640 x 480 view (focal 600 px) of a 2 x 1.5 plane 3 units
// away, facing the viewer, with a 256 x 192 texel texture.
Camera clip_camera() { return make_camera(600.0, 640, 480); }

PlanePose clip_start() {
  PlanePose pose;
  pose.point = Vec3(0.0, 0.0, 3.0);
  pose.normal = Vec3(0.0, 0.0, -1.0);
  pose.size = Vec2(2.0, 1.5);
  pose.texture_size = glm::ivec2(256, 192);
  return pose;
}

}  // namespace

double clip_measured_error(const StudyCondition& condition, double threshold_px) {
  const int frames = int(std::lround(kClipSeconds * kClipFrameRate));
  // Turning about the vertical axis through the plane's centre, radians per frame.
  ScriptSegment turn;
  turn.frames = frames;
  turn.omega = Vec3(0.0, condition.speed_deg_s * kPi / 180.0 / kClipFrameRate, 0.0);
  const std::vector<ScriptFrame> clip =
      expand_segments(clip_start(), MotionModel::kSpinAboutCentre, {turn});
  EngineSettings settings;
  settings.policy = &reuse_policy(study_policy_name(condition.policy));
  settings.thresholds = {threshold_px, threshold_px, threshold_px, threshold_px};
  PlaneEngine engine(clip_camera(), make_layer(Image(256, 192, Pixel{255, 255, 255, 255})),
                     settings);
  double largest = engine.start(clip[0].pose).measured_error_px;
  for (size_t i = 1; i < clip.size(); ++i) {
    const FrameReport r = engine.advance(clip[i - 1].pose, clip[i - 1].motion, clip[i].pose);
    if (r.visible && std::isfinite(r.measured_error_px))
      largest = std::max(largest, r.measured_error_px);
  }
  return largest;
}

ErrorLadder play_error_ladder(const StudyCondition& condition, double min_px, double max_px,
                              int steps) {
  ErrorLadder ladder;
  for (int i = 0; i < steps; ++i) {
    const double t = min_px * std::pow(max_px / min_px, double(i) / double(steps - 1));
    ladder.thresholds_px.push_back(t);
    ladder.measured_px.push_back(clip_measured_error(condition, t));
  }
  return ladder;
}

double shown_error(const ErrorLadder& ladder, double requested_px) {
  double best = ladder.measured_px.front();
  const auto distance = [&](double m) {
    return std::abs(std::log(std::max(m, 1e-6)) - std::log(requested_px));
  };
  for (double m : ladder.measured_px) {
    if (distance(m) < distance(best) || (distance(m) == distance(best) && m < best)) best = m;
  }
  return best;
}

ErrorDisplay engine_error_display(const Study& study) {
  // The ladders played so far in this process, by what decides them (under a lock: a window
  // may run studies on more than one thread).
  using Key = std::tuple<int, double, double, double>;
  static std::mutex lock;
  static std::map<Key, ErrorLadder> played;
  auto ladders = std::make_shared<std::vector<ErrorLadder>>();
  for (const StudyCondition& c : study.conditions) {
    const std::lock_guard<std::mutex> hold(lock);
    const Key key{int(c.policy), c.speed_deg_s, study.min_px, study.max_px};
    if (!played.count(key)) {
      played[key] = play_error_ladder(c, study.min_px, study.max_px, kLadderSteps);
    }
    ladders->push_back(played[key]);
  }
  return [ladders](int condition, double requested_px) {
    return shown_error((*ladders)[size_t(condition)], requested_px);
  };
}

}  // namespace oflab

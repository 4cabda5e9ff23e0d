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

PlanePose clip_start() {
  PlanePose pose;
  pose.point = Vec3(0.0, 0.0, 3.0);
  pose.normal = Vec3(0.0, 0.0, -1.0);
  pose.size = Vec2(2.0, 1.5);
  pose.texture_size = glm::ivec2(kClipTextureWidth, kClipTextureHeight);
  return pose;
}

}  // namespace

Camera clip_camera() { return make_camera(600.0, kClipWidth, kClipHeight); }

std::vector<ScriptFrame> clip_script(const StudyCondition& condition) {
  const int frames = int(std::lround(kClipSeconds * kClipFrameRate));
  // Turning about the vertical axis through the plane's centre, radians per frame.
  ScriptSegment turn;
  turn.frames = frames;
  turn.omega = Vec3(0.0, condition.speed_deg_s * kPi / 180.0 / kClipFrameRate, 0.0);
  return expand_segments(clip_start(), MotionModel::kSpinAboutCentre, {turn});
}

double play_reused_clip(const StudyCondition& condition, double threshold_px, Layer texture,
                        const std::function<void(const PlaneEngine&, const FrameReport&)>& shown) {
  const std::vector<ScriptFrame> clip = clip_script(condition);
  EngineSettings settings;
  settings.policy = &reuse_policy(study_policy_name(condition.policy));
  settings.thresholds = {threshold_px, threshold_px, threshold_px, threshold_px};
  PlaneEngine engine(clip_camera(), std::move(texture), settings);
  double largest = 0.0;
  for (size_t i = 0; i < clip.size(); ++i) {
    const FrameReport r = i == 0
                              ? engine.start(clip[0].pose)
                              : engine.advance(clip[i - 1].pose, clip[i - 1].motion, clip[i].pose);
    if (r.visible && std::isfinite(r.measured_error_px))
      largest = std::max(largest, r.measured_error_px);
    if (shown) shown(engine, r);
  }
  return largest;
}

double clip_measured_error(const StudyCondition& condition, double threshold_px) {
  return play_reused_clip(
      condition, threshold_px,
      make_layer(Image(kClipTextureWidth, kClipTextureHeight, Pixel{255, 255, 255, 255})), {});
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

int shown_rung(const ErrorLadder& ladder, double requested_px) {
  const auto distance = [&](double m) {
    return std::abs(std::log(std::max(m, 1e-6)) - std::log(requested_px));
  };
  int best = 0;
  for (int i = 1; i < int(ladder.measured_px.size()); ++i) {
    const double m = ladder.measured_px[size_t(i)];
    const double b = ladder.measured_px[size_t(best)];
    if (distance(m) < distance(b) || (distance(m) == distance(b) && m < b)) best = i;
  }
  return best;
}

double shown_error(const ErrorLadder& ladder, double requested_px) {
  return ladder.measured_px[size_t(shown_rung(ladder, requested_px))];
}

std::vector<ErrorLadder> study_ladders(const Study& study) {
  // The ladders played so far in this process, by what decides them (under a lock: a window
  // may run studies on more than one thread).
  using Key = std::tuple<int, double, double, double>;
  static std::mutex lock;
  static std::map<Key, ErrorLadder> played;
  std::vector<ErrorLadder> ladders;
  for (const StudyCondition& c : study.conditions) {
    const std::lock_guard<std::mutex> hold(lock);
    const Key key{int(c.policy), c.speed_deg_s, study.min_px, study.max_px};
    if (!played.count(key)) {
      played[key] = play_error_ladder(c, study.min_px, study.max_px, kLadderSteps);
    }
    ladders.push_back(played[key]);
  }
  return ladders;
}

ErrorDisplay engine_error_display(const Study& study) {
  auto ladders = std::make_shared<std::vector<ErrorLadder>>(study_ladders(study));
  return [ladders](int condition, double requested_px) {
    return shown_error((*ladders)[size_t(condition)], requested_px);
  };
}

}  // namespace oflab

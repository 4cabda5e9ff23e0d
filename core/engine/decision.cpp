// Flow measures and level choice (dissertation section 5.4.5, corrected: absolute values,
// per-corner bounds in pixels, a fourth "higher order" term with the right units, and
// budgets on the total neglected error; see manual/animation.md).
#include "engine/decision.h"

#include <algorithm>
#include <cmath>

#include "flow/homography.h"

namespace oflab {

namespace {

struct LevelWords {
  const char* name;
  const char* title;
};

// Indexed by static_cast<int>(Level).
constexpr LevelWords kLevelWords[kLevelCount] = {{"none", "none"},
                                                 {"translate", "translate"},
                                                 {"affine", "affine"},
                                                 {"perspective", "perspective"},
                                                 {"rerender", "re-render"}};

}  // namespace

const char* level_name(Level level) { return kLevelWords[static_cast<int>(level)].name; }

const char* level_title(Level level) { return kLevelWords[static_cast<int>(level)].title; }

bool parse_level(const std::string& text, Level* level) {
  for (int l = 0; l < kLevelCount; ++l) {
    if (text != kLevelWords[l].name) continue;
    *level = static_cast<Level>(l);
    return true;
  }
  return false;
}

FlowMeasures measure_flow(const Camera& camera, const PlanePose& pose, const RigidMotion& motion,
                          const std::vector<Vec2>& corners_centred) {
  FlowMeasures m;
  for (const Vec2& c : corners_centred) m.expansion_point += c;
  m.expansion_point /= static_cast<double>(corners_centred.size());
  const PlanarFlowCoefficients k =
      reexpand(planar_flow_coefficients(camera, pose, motion), m.expansion_point);
  m.flow[0] = glm::length(Vec2(k.tx, k.ty));
  for (const Vec2& c : corners_centred) {
    const Vec2 d = c - m.expansion_point;
    m.size = std::max(m.size, glm::length(d));
    const Vec2 first(k.j11 * d.x + k.j12 * d.y, k.j21 * d.x + k.j22 * d.y);
    const double q = k.px * d.x + k.py * d.y;
    m.flow[1] = std::max(m.flow[1], glm::length(first));
    m.flow[2] = std::max(m.flow[2], glm::length(q * d));
    const Vec2 residual = 0.5 * image_acceleration(camera, pose, motion, c) - q * flow_at(k, c);
    m.flow[3] = std::max(m.flow[3], glm::length(residual));
  }
  return m;
}

TermArray measure_printed_flow(const Camera& camera, const PlanePose& pose,
                               const RigidMotion& motion,
                               const std::vector<Vec2>& corners_centred) {
  const PlanarFlowCoefficients k = planar_flow_coefficients(camera, pose, motion);
  Vec2 lo = corners_centred.front(), hi = lo;
  for (const Vec2& c : corners_centred) {
    lo = glm::min(lo, c);
    hi = glm::max(hi, c);
  }
  const double size = std::max(hi.x - lo.x, hi.y - lo.y);
  const double omega = glm::length(motion.omega);
  return {std::max(std::abs(k.tx), std::abs(k.ty)),
          std::max({std::abs(k.j11), std::abs(k.j12), std::abs(k.j21), std::abs(k.j22)}) * size,
          std::max(std::abs(k.px), std::abs(k.py)) * size * size, omega * omega * size * size};
}

Level printed_cascade(const TermArray& accumulated, const TermArray& flow,
                      const TermArray& thresholds) {
  for (int k = kTermCount - 1; k >= 0; --k) {
    if (accumulated[k] + flow[k] > thresholds[k]) return static_cast<Level>(k + 1);
  }
  return Level::kNone;
}

double neglected_error(const TermArray& accumulated, const TermArray& flow, Level level) {
  double sum = 0.0;
  for (int k = static_cast<int>(level); k < kTermCount; ++k) sum += accumulated[k] + flow[k];
  return sum;
}

Level choose_level(const TermArray& accumulated, const TermArray& flow, const TermArray& thresholds,
                   const LevelSet& allowed) {
  return choose_level(accumulated, flow, thresholds, allowed, TermArray{});
}

Level choose_level(const TermArray& accumulated, const TermArray& flow, const TermArray& thresholds,
                   const LevelSet& allowed, const TermArray& pending) {
  for (int l = 0; l < kTermCount; ++l) {
    const Level level = static_cast<Level>(l);
    if (!allowed[l]) continue;
    if (neglected_error(accumulated, flow, level) <= thresholds[l] && pending[l] <= thresholds[l]) {
      return level;
    }
  }
  return Level::kRerender;
}

}  // namespace oflab

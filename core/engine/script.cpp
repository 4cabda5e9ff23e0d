#include "engine/script.h"

namespace oflab {

std::vector<ScriptFrame> expand_segments(const PlanePose& initial, MotionModel model,
                                         const std::vector<ScriptSegment>& segments) {
  std::vector<ScriptFrame> frames;
  PlanePose pose = initial;
  for (const ScriptSegment& s : segments) {
    for (int i = 0; i < s.frames; ++i) {
      ScriptFrame f;
      f.pose = pose;
      f.motion.velocity = s.velocity;
      f.motion.omega = s.omega;
      f.motion.model = model;
      frames.push_back(f);
      pose = advance_pose(pose, rigid_step(f.motion, pose, 1.0));
    }
  }
  return frames;
}

}  // namespace oflab

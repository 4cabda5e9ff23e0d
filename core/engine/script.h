// Motion scripts (dissertation section 5.2.1 and 6.4): for every frame, the plane's pose
// and its velocities towards the next frame. Velocities are per frame: world units per
// frame and radians per frame, in the viewer frame (see core/flow/motion.h for the models).
// Reading scripts from files is analysis/formats/script_file.h; this is the data model.
#pragma once

#include <string>
#include <vector>

#include "flow/camera.h"
#include "flow/motion.h"
#include "flow/plane.h"

namespace oflab {

struct ScriptFrame {
  PlanePose pose;      // pose shown at this frame
  RigidMotion motion;  // motion from this frame to the next (dt = 1 frame)
};

struct MotionScript {
  std::string name;
  std::string description;
  Camera camera;
  std::vector<ScriptFrame> frames;
};

// A stretch of frames with constant per-frame velocities.
struct ScriptSegment {
  int frames = 0;  // number of frames this segment contributes (>= 1)
  Vec3 velocity{0.0};
  Vec3 omega{0.0};
};

// Expands segments into frames: frame 0 shows `initial`, and each next pose is the exact
// rigid step of the previous frame's motion under `model` (core/flow/motion.h).
// Precondition: every segment has frames >= 1.
std::vector<ScriptFrame> expand_segments(const PlanePose& initial, MotionModel model,
                                         const std::vector<ScriptSegment>& segments);

}  // namespace oflab

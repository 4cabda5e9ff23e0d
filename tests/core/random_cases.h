// Random but valid cameras, plane poses and motions for property tests (fixed seeds).
#pragma once

#include <random>
#include <vector>

#include "flow/camera.h"
#include "flow/motion.h"
#include "flow/plane.h"

namespace oflab::testing {

struct FlowCase {
  Camera camera;
  PlanePose pose;
  RigidMotion motion;
};

// A plane 1.5-6 units in front of the eye, tilted up to ~60 degrees, with moderate
// velocities; every third case is an edge-on-through-the-axis plane (N3 = 0) or a pure
// rotation, so the special cases are always exercised.
inline FlowCase random_flow_case(std::mt19937& rng, int index) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  FlowCase c;
  c.camera = make_camera(300.0 + 400.0 * (0.5 + 0.5 * u(rng)), 640, 480);
  c.pose.point = Vec3(0.4 * u(rng), 0.4 * u(rng), 3.75 + 2.25 * u(rng));
  c.pose.normal = Vec3(0.6 * u(rng), 0.6 * u(rng), 1.0);
  if (index % 3 == 1) c.pose.normal = Vec3(1.0, 0.3 * u(rng), 0.0);  // N3 = 0
  c.pose.up = Vec3(0.1 * u(rng), -1.0, 0.1 * u(rng));
  c.pose.size = Vec2(0.8, 0.6);
  c.motion.velocity = Vec3(0.5 * u(rng), 0.5 * u(rng), 0.5 * u(rng));
  c.motion.omega = Vec3(0.6 * u(rng), 0.6 * u(rng), 0.6 * u(rng));
  if (index % 3 == 2) c.motion.velocity = Vec3(0.0);  // pure rotation
  c.motion.model = static_cast<MotionModel>(index % 3 == 0 ? 0 : (index / 3) % 3);
  return c;
}

// The worked example of manual/flow-math.md section 4.2 ("Default case"): a tilted
// 1.0 x 0.8 plane at depth 3 with a general screw motion, f = 600 px, 800 x 600 image.
inline FlowCase default_case() {
  FlowCase c;
  c.camera = make_camera(600.0, 800, 600);
  c.pose.point = Vec3(0.15, -0.1, 3.0);
  c.pose.normal = Vec3(0.25, -0.15, 1.0);
  c.pose.up = Vec3(0.0, -1.0, 0.0);
  c.pose.size = Vec2(1.0, 0.8);
  c.pose.texture_size = glm::ivec2(243, 198);
  c.motion.velocity = Vec3(0.3, -0.2, 0.5);
  c.motion.omega = Vec3(0.4, -0.3, 0.6);
  return c;
}

// Centred pixel positions where the plane of `c` is seen in front of the eye: the images of
// interior points of the plane rectangle.
inline std::vector<Vec2> sample_plane_pixels(const FlowCase& c) {
  std::vector<Vec2> out;
  const auto corners = plane_corners(c.pose);
  for (double a : {0.2, 0.5, 0.8}) {
    for (double b : {0.2, 0.5, 0.8}) {
      const Vec3 r = corners[0] + a * (corners[1] - corners[0]) + b * (corners[3] - corners[0]);
      if (r.z > 0.1) out.push_back(project_centred(c.camera, r));
    }
  }
  return out;
}

}  // namespace oflab::testing

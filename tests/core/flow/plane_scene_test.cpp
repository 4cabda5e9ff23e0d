// The flow views' scene: the default demo is drawable, and each way a scene cannot be drawn
// is named.
#include "flow/plane_scene.h"

#include <gtest/gtest.h>

#include <glm/glm.hpp>

namespace oflab {
namespace {

TEST(PlaneScene, DemoIsValidAndImpossibleScenesAreNamed) {
  PlaneScene s = default_demo_scene();
  EXPECT_EQ(plane_scene_problem(s), "");
  s.pose.point = s.pose.point * (-1.0 / s.pose.point.z);  // same ray, centre at depth -1
  EXPECT_NE(plane_scene_problem(s).find("behind"), std::string::npos);
  s = default_demo_scene();
  s.pose.normal = glm::cross(s.pose.point, Vec3(0, 1, 0));  // N.P = 0
  EXPECT_NE(plane_scene_problem(s).find("eye"), std::string::npos);
  s = default_demo_scene();
  s.pose.point = Vec3(0.15, -0.1, 0.3);  // centre in front, a corner behind the eye
  s.pose.normal = Vec3(1.0, 0.0, 0.2);
  EXPECT_NE(plane_scene_problem(s).find("corner"), std::string::npos);
  s = default_demo_scene();
  s.camera.focal_px = 0.0;
  EXPECT_NE(plane_scene_problem(s).find("focal"), std::string::npos);
}

}  // namespace
}  // namespace oflab

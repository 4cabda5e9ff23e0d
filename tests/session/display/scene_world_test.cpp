// A scene's world (session/display/world_geometry.h scene_world_loop, scene_world_frame), the
// one the desktop's and the page's world views draw, against what core's scene animator and
// viewer poses say, computed independently here: the eye's place from the pose, the image
// plane seen back from the viewer, the polygons' colours from their statuses and levels.
#include <gtest/gtest.h>

#include <memory>

#include "display/world_geometry.h"
#include "formats/scene_file.h"
#include "formats/viewer_script_file.h"
#include "scene/scene_animator.h"

namespace oflab::test {
namespace {

constexpr double kSecondsPerFrame = 1.0 / 30.0;

std::unique_ptr<SceneScriptAnimator> street_walk() {
  auto scene = std::make_shared<const Scene>(read_scene_file(resolve_scene_path("street")));
  const ViewerScript walk = read_viewer_script_file(resolve_viewer_script_path("walk"));
  return make_scene_animator(scene, walk, SceneSettings{});
}

// The eye in world coordinates: X_viewer = Q X_world + s is 0 at X_world = -Q^T s.
Vec3 eye_of(const ViewerPose& pose) { return -(glm::transpose(pose.rotation) * pose.translation); }

TEST(SceneWorld, LoopHoldsThePolygonsAndTheEyesPath) {
  const auto animator = street_walk();
  const SceneWorldLoop loop = scene_world_loop(*animator, kSecondsPerFrame);
  ASSERT_EQ(loop.outlines.size(), animator->scene().polygons.size());
  EXPECT_EQ(loop.outlines[0], polygon_vertices(animator->scene().polygons[0]));
  const ViewerScript& walk = animator->script();
  ASSERT_EQ(loop.path.size(), walk.frames.size());
  for (size_t k = 0; k < walk.frames.size(); k += 17) {
    EXPECT_NEAR(glm::length(loop.path[k] - eye_of(walk.frames[k].pose)), 0.0, 1e-9) << k;
  }
  double largest = 0.0;
  for (const ViewerFrame& f : walk.frames)
    largest = std::max(largest, glm::length(f.motion.velocity));
  EXPECT_NEAR(loop.largest_velocity, largest / kSecondsPerFrame, 1e-9);
  EXPECT_GT(loop.depth, 0.0);
  EXPECT_DOUBLE_EQ(loop.full_arrow, 2.0 * loop.depth);
}

TEST(SceneWorld, FramePlacesTheEyeAndColoursThePolygonsByStatus) {
  const auto animator = street_walk();
  const SceneWorldLoop loop = scene_world_loop(*animator, kSecondsPerFrame);
  animator->start();
  for (int k = 0; k < 20; ++k) animator->advance();
  const SceneWorldFrame f = scene_world_frame(loop, *animator, kSecondsPerFrame);
  const ViewerPose pose = animator->script().frames[20].pose;
  EXPECT_NEAR(glm::length(f.eye - eye_of(pose)), 0.0, 1e-9);
  EXPECT_EQ(f.path_index, 20);
  EXPECT_TRUE(f.walking);
  // The image plane's corners, seen back from the viewer, are the camera's image plane.
  const std::array<Vec3, 4> corners = image_plane_corners(loop.camera, loop.depth);
  for (size_t k = 0; k < 4; ++k) {
    EXPECT_NEAR(glm::length(to_view(pose, f.image_corners[k]) - corners[k]), 0.0, 1e-9) << k;
  }
  const std::vector<PolygonStatus>& statuses = animator->renderer().statuses();
  const std::vector<Level>& levels = animator->renderer().levels();
  ASSERT_EQ(f.colours.size(), statuses.size());
  // The colour each status gets, written out here: drawn in its level's (clipped: re-rendered),
  // culled pale, hidden dark, starved black.
  int drawn = 0;
  for (size_t k = 0; k < statuses.size(); ++k) {
    Rgb8 want{0, 0, 0};
    switch (statuses[k]) {
      case PolygonStatus::kAnimated:
        want = level_colour(levels[k]), ++drawn;
        break;
      case PolygonStatus::kClipped:
        want = level_colour(Level::kRerender), ++drawn;
        break;
      case PolygonStatus::kBackFacing:
      case PolygonStatus::kOutsideFrustum:
        want = {215, 215, 215};
        break;
      case PolygonStatus::kHidden:
        want = {70, 70, 70};
        break;
      case PolygonStatus::kStarved:
        break;
    }
    const Rgb8 c = f.colours[k];
    EXPECT_TRUE(c.r == want.r && c.g == want.g && c.b == want.b)
        << k << " " << polygon_status_name(statuses[k]);
  }
  EXPECT_GT(drawn, 0);
  // The control: the status decides, not the level alone (a hidden affine polygon is dark).
  const Rgb8 hidden = scene_polygon_colour(PolygonStatus::kHidden, Level::kAffine);
  const Rgb8 affine = scene_polygon_colour(PolygonStatus::kAnimated, Level::kAffine);
  EXPECT_FALSE(hidden.r == affine.r && hidden.g == affine.g && hidden.b == affine.b);
}

}  // namespace
}  // namespace oflab::test

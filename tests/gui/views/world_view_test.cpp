// The world view (gui/views/world_view.h) and its geometry (gui/adapters/world_geometry.h):
// the geometry against core's own projection and poses, the picture at 1920 x 1080 in both
// looks against baselines (with controls: a picture without the arrows and the frustum is
// rejected, and each part hidden on its own changes the picture), and frames that move the
// plane without making a single actor anew.
#include "views/world_view.h"

#include <vtkActor.h>
#include <vtkActorCollection.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkRenderer.h>

#include <cmath>
#include <set>

#include "adapters/world_geometry.h"
#include "app/view_table.h"
#include "flow/plane_scene.h"
#include "image_checks.h"
#include "models/scene_model.h"
#include "window_fixture.h"

namespace oflab::test {
namespace {

// Pixel of a point on the image plane, read off the drawn rectangle's corners by linear
// interpolation (independent of the formula that placed them).
Vec2 pixel_on_image_plane(const std::array<Vec3, 4>& corners, const Camera& camera,
                          const Vec3& point) {
  const double u = (point.x - corners[0].x) / (corners[1].x - corners[0].x);
  const double v = (point.y - corners[0].y) / (corners[3].y - corners[0].y);
  return {u * camera.width, v * camera.height};
}

TEST(WorldGeometry, ImagePlaneCornersProjectToThePixelCorners) {
  const Camera camera{600.0, 380.0, 310.0, 800, 600};
  const std::array<Vec3, 4> corners = image_plane_corners(camera, 0.7);
  const Vec2 expected[4] = {{0, 0}, {800, 0}, {800, 600}, {0, 600}};
  for (int k = 0; k < 4; ++k) {
    EXPECT_NEAR(corners[size_t(k)].z, 0.7, 1e-15);
    const Vec2 pixel = centred_to_pixel(camera, project_centred(camera, corners[size_t(k)]));
    EXPECT_NEAR(pixel.x, expected[k].x, 1e-9) << k;
    EXPECT_NEAR(pixel.y, expected[k].y, 1e-9) << k;
  }
}

TEST(WorldGeometry, RaysCrossTheImagePlaneAtThePlaneCornersPixels) {
  const PlaneScene scene = default_demo_scene();
  const double depth = 0.9;
  const std::array<Vec3, 4> image = image_plane_corners(scene.camera, depth);
  for (const Vec3& corner : plane_corners(scene.pose)) {
    const Vec3 crossing = ray_at_depth(corner, depth);
    EXPECT_NEAR(crossing.z, depth, 1e-15);
    // On the ray: parallel to the corner.
    EXPECT_NEAR(glm::length(glm::cross(crossing, corner)), 0.0, 1e-12);
    const Vec2 drawn = pixel_on_image_plane(image, scene.camera, crossing);
    const Vec2 seen = centred_to_pixel(scene.camera, project_centred(scene.camera, corner));
    EXPECT_NEAR(drawn.x, seen.x, 1e-9);
    EXPECT_NEAR(drawn.y, seen.y, 1e-9);
  }
}

TEST(WorldGeometry, ImageDepthsSitBetweenTheEyeAndTheScene) {
  EXPECT_DOUBLE_EQ(plane_image_depth({{0, 0, 3}, {1, 0, 2}, {0, 1, 5}}), 1.0);
  EXPECT_DOUBLE_EQ(plane_image_depth({}), 1.0);
  EXPECT_DOUBLE_EQ(scene_image_depth({{0, 0, 0}, {3, 4, 0}}), 0.5);
  EXPECT_DOUBLE_EQ(scene_image_depth({{1, 1, 1}}), 1.0);
}

TEST(WorldGeometry, ArrowLengthsStayReadableAndOrdered) {
  EXPECT_EQ(arrow_length(0.0, 2.0, 1.0), 0.0);
  EXPECT_DOUBLE_EQ(arrow_length(2.0, 2.0, 1.0), 1.0);
  EXPECT_DOUBLE_EQ(arrow_length(1e-6, 2.0, 1.0), 0.35 + 0.65 * 5e-7);
  EXPECT_LT(arrow_length(0.5, 2.0, 1.0), arrow_length(1.0, 2.0, 1.0));
  EXPECT_DOUBLE_EQ(arrow_length(5.0, 2.0, 1.0), 1.0);  // beyond the largest: clamped
}

Vec3 transform_point(const std::array<double, 16>& m, const Vec3& p) {
  Vec3 out;
  for (int r = 0; r < 3; ++r) {
    out[r] = m[size_t(4 * r)] * p.x + m[size_t(4 * r + 1)] * p.y + m[size_t(4 * r + 2)] * p.z +
             m[size_t(4 * r + 3)];
  }
  return out;
}

TEST(WorldGeometry, ArrowMatrixMapsTheUnitArrowOntoTheVector) {
  const Vec3 origin(0.2, -0.1, 2.0), direction(-0.7, 0.7, 0.1);
  const std::array<double, 16> m = arrow_matrix(origin, direction, 0.4);
  const Vec3 tail = transform_point(m, Vec3(0.0)), tip = transform_point(m, Vec3(1, 0, 0));
  EXPECT_NEAR(glm::length(tail - origin), 0.0, 1e-15);
  EXPECT_NEAR(glm::length(tip - (origin + 0.4 * glm::normalize(direction))), 0.0, 1e-12);
  const Vec3 y = transform_point(m, Vec3(0, 1, 0)) - origin,
             z = transform_point(m, Vec3(0, 0, 1)) - origin;
  EXPECT_NEAR(glm::dot(y, tip - origin), 0.0, 1e-12);  // round: a uniform, rigid scale
  EXPECT_NEAR(glm::dot(z, y), 0.0, 1e-12);
  EXPECT_NEAR(glm::length(y), 0.4, 1e-12);
  EXPECT_NEAR(glm::dot(glm::cross(tip - origin, y), z), 0.4 * 0.4 * 0.4, 1e-12);  // proper
  const std::array<double, 16> none = arrow_matrix(origin, Vec3(0.0), 0.4);
  EXPECT_NEAR(glm::length(transform_point(none, Vec3(1, 1, 1)) - origin), 0.0, 1e-15);
}

TEST(WorldGeometry, ViewerToWorldUndoesTheViewerPose) {
  const ViewerPose pose = look_at(Vec3(1.0, 2.0, -3.0), Vec3(0.5, 0.0, 1.0), Vec3(0, 1, 0));
  const Vec3 world(0.3, -1.2, 4.5);
  const Vec3 viewer = pose.rotation * world + pose.translation;
  EXPECT_NEAR(glm::length(viewer_to_world(pose, viewer) - world), 0.0, 1e-12);
  EXPECT_NEAR(glm::length(transform_point(viewer_to_world_matrix(pose), viewer) - world), 0.0,
              1e-12);
  EXPECT_NEAR(glm::length(viewer_to_world(pose, Vec3(0.0)) - Vec3(1.0, 2.0, -3.0)), 0.0, 1e-12);
}

class WorldViewTest : public WindowTest {
 protected:
  WorldView& world() { return *view_page<WorldView>(window(), "world"); }
  void show_world(bool presentation) {
    window().resize(1920, 1080);
    window().model()->set_presentation(presentation);
    window().set_external_clock(true);
    ASSERT_TRUE(window().show_view("world"));
    QApplication::processEvents();
    window().play_frames(10);
  }
  std::set<vtkProp*> props() {
    std::set<vtkProp*> all;
    vtkPropCollection* collection = world().renderer()->GetViewProps();
    collection->InitTraversal();
    while (vtkProp* p = collection->GetNextProp()) all.insert(p);
    return all;
  }
  // The rendered view compared with baselines/<name>.png (image_checks.h).
  void expect_matches_baseline(const QImage& rendered, const QString& name) {
    test::expect_matches_baseline(rendered, name, kWorldBaselineWidth);
  }
  // The world view's baselines keep the thin lines and arrows of a 1920-pixel view visible.
  static constexpr int kWorldBaselineWidth = 640;
};

TEST_F(WorldViewTest, TheWorldViewFollowsTheFlowViewInTheTable) {
  const std::vector<std::string> names = view_table_names();
  ASSERT_GE(names.size(), 2u);
  EXPECT_EQ(names[0], "flow");
  EXPECT_EQ(names[1], "world");
}

TEST_F(WorldViewTest, WorldViewOfTheDemoMatchesItsBaseline) {
  show_world(false);
  expect_matches_baseline(world().render_image(), "world-demo");
}

TEST_F(WorldViewTest, WorldViewInPresentationModeMatchesItsBaseline) {
  show_world(true);
  EXPECT_GE(world().smallest_text_px(), kPresentationMinTextPx);
  expect_matches_baseline(world().render_image(), "world-demo-presentation");
}

TEST_F(WorldViewTest, ToleranceCatchesAWorldViewWithoutArrowsAndFrustum) {
  show_world(false);
  const QImage baseline(QStringLiteral(OFLAB_GUI_BASELINES "/world-demo.png"));
  ASSERT_FALSE(baseline.isNull()) << "missing baseline world-demo.png";
  for (WorldPart part : {WorldPart::kVelocity, WorldPart::kOmega, WorldPart::kFrustum}) {
    world().set_part_shown(part, false);
  }
  const QImage rendered = scaled_rgb(world().render_image(), baseline.size());
  EXPECT_LT(psnr_db(baseline, rendered), kBaselinePsnrDb);
}

TEST_F(WorldViewTest, FrustumPlaneBothArrowsAndPathAreEachDrawn) {
  for (bool presentation : {false, true}) {
    show_world(presentation);
    const QImage full = world().render_image();
    for (WorldPart part :
         {WorldPart::kFrustum, WorldPart::kImagePlane, WorldPart::kPlane, WorldPart::kVelocity,
          WorldPart::kOmega, WorldPart::kRays, WorldPart::kPath}) {
      world().set_part_shown(part, false);
      const QImage without = world().render_image();
      world().set_part_shown(part, true);
      // At least 800 pixels of a 1920 x 1080 window belong to each part (the thinnest, the
      // path, has over 1000; a part not drawn changes none).
      EXPECT_GT(changed_fraction(full, without) * full.width() * full.height(), 800.0)
          << "part " << int(part) << (presentation ? " in presentation mode" : "");
    }
  }
}

TEST_F(WorldViewTest, SteppingMovesThePlaneWithoutMakingActorsAnew) {
  show_world(false);
  world().render_image();
  const std::set<vtkProp*> before = props();
  const QImage first = world().render_image();
  SceneModel* scene = window().model()->scene();
  for (int step = 0; step < 5; ++step) {
    window().play_frames(1);  // what the Step key does, and each tick of play
    const Vec3 expected = scene->current_pose().point;
    EXPECT_NEAR(glm::length(world().drawn_centre() - expected), 0.0, 1e-12) << step;
  }
  scene->set_frame(40);  // the scrub slider
  QApplication::processEvents();
  EXPECT_NEAR(glm::length(world().drawn_centre() - scene->current_pose().point), 0.0, 1e-12);
  EXPECT_GT(changed_fraction(first, world().render_image()), 0.002);
  EXPECT_EQ(props(), before);  // the same objects: nothing was made anew
}

TEST_F(WorldViewTest, ASceneSourceShowsItsPolygonsWithTheSameActors) {
  show_world(false);
  const std::set<vtkProp*> before = props();
  ASSERT_TRUE(window().model()->animation()->set_source({"scene", "four-cubes", "circle"}))
      << window().message().toStdString();
  window().play_frames(5);
  const QImage image = world().render_image();
  EXPECT_TRUE(world().scene_mode());
  const Animator* animator = window().model()->animation()->animator();
  ASSERT_NE(animator, nullptr);
  const Vec3 eye = viewer_to_world(animator->view(), Vec3(0.0));
  EXPECT_NEAR(glm::length(world().drawn_centre() - eye), 0.0, 1e-12);
  EXPECT_GT(distinct_colours(image), 50);
  EXPECT_EQ(props(), before);
}

}  // namespace
}  // namespace oflab::test

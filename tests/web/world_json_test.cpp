// The page's world view numbers (web/world_json.h) are the teaching layer's plane world
// (session/display/world_geometry.h), the one the desktop's world view draws, to the bit:
// the loop and the frame of a panel playing a script, read back from the JSON.
#include "world_json.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "formats/scene_file.h"
#include "formats/viewer_script_file.h"
#include "scene/scene_animator.h"

namespace oflab::test {
namespace {

using json = nlohmann::json;

void expect_point(const json& p, const Vec3& expected, const std::string& what) {
  ASSERT_EQ(p.size(), 3u) << what;
  for (int i = 0; i < 3; ++i)
    EXPECT_EQ(p[size_t(i)].get<double>(), expected[i]) << what << " " << i;
}

// A panel playing a plane that drifts, turns and comes nearer over 20 frames.
PlanePanel drifting_panel(int frame) {
  PlanePanel panel(Image(64, 48, Pixel{200, 100, 50, 255}));
  MotionScript script;
  script.camera = panel.scene().camera;
  PlanePose pose = panel.scene().pose;
  for (int k = 0; k < 20; ++k) {
    RigidMotion motion;
    motion.velocity = Vec3(0.004, -0.002 * k, -0.01);
    motion.omega = Vec3(0.001 * k, 0.0, 0.02);
    script.frames.push_back({pose, motion});
    pose.point += Vec3(0.004, -0.002 * k, -0.01);
  }
  EXPECT_EQ(panel.set_script(script, "drift"), "");
  panel.set_frame(frame);
  return panel;
}

TEST(WorldJson, LoopIsTheTeachingLayersPlaneLoop) {
  const PlanePanel panel = drifting_panel(7);
  const PlaneWorldLoop loop = panel_world_loop(panel);
  const PlaneWorldLoop expected = plane_world_loop(
      panel.as_script(), panel.scene().camera, panel.current_pose(), PlanePanel::kSecondsPerFrame);
  const json out = json::parse(world_loop_json(loop, ""));
  EXPECT_EQ(out["depth"].get<double>(), expected.depth);
  EXPECT_EQ(out["full_arrow"].get<double>(), expected.full_arrow);
  EXPECT_EQ(out["largest_velocity"].get<double>(), expected.largest_velocity);
  ASSERT_EQ(out["path"].size(), expected.path.size());
  for (size_t k = 0; k < expected.path.size(); ++k)
    expect_point(out["path"][k], expected.path[k], "path");
  const std::array<Vec3, 4> image = image_plane_corners(expected.camera, expected.depth);
  for (size_t k = 0; k < 4; ++k) expect_point(out["image_corners"][k], image[k], "image corner");
  EXPECT_EQ(out["caption"].get<std::string>(), plane_world_caption(expected));
  // Every corner of the loop lies inside the bounds.
  const json& b = out["bounds"];
  for (const Vec3& c : expected.loop_corners) {
    for (int i = 0; i < 3; ++i) {
      EXPECT_LE(b[size_t(2 * i)].get<double>(), c[i]);
      EXPECT_GE(b[size_t(2 * i + 1)].get<double>(), c[i]);
    }
  }
}

TEST(WorldJson, FrameIsTheTeachingLayersPlaneFrame) {
  const PlanePanel panel = drifting_panel(7);
  const PlaneWorldLoop loop = panel_world_loop(panel);
  const PlaneWorldFrame f =
      plane_world_frame(loop, panel.current_pose(), panel.current_motion(), panel.frame());
  const json out = json::parse(world_frame_json(loop, panel));
  EXPECT_EQ(out["frame"].get<int>(), 7);
  EXPECT_EQ(out["path_index"].get<int>(), 7);
  for (size_t k = 0; k < 4; ++k)
    expect_point(out["plane_corners"][k], f.plane_corners[k], "corner");
  ASSERT_EQ(out["ray_images"].size(), f.ray_images.size());
  for (size_t k = 0; k < f.ray_images.size(); ++k)
    expect_point(out["ray_images"][k], f.ray_images[k], "ray image");
  expect_point(out["velocity"], f.velocity, "V");
  expect_point(out["omega"], f.omega, "Omega");
  const std::pair<const char*, WorldArrow> arrows[] = {{"velocity", f.motion.velocity},
                                                       {"omega", f.motion.omega},
                                                       {"normal", f.normal},
                                                       {"up", f.up}};
  for (const auto& [name, arrow] : arrows) {
    const std::array<double, 16> m = arrow_matrix(arrow);
    const json& got = out["arrows"][name]["matrix"];
    ASSERT_EQ(got.size(), 16u) << name;
    for (size_t i = 0; i < 16; ++i) EXPECT_EQ(got[i].get<double>(), m[i]) << name << " " << i;
    EXPECT_EQ(out["arrows"][name]["length"].get<double>(), arrow.length) << name;
  }
  EXPECT_GT(f.motion.velocity.length, 0.0);  // the script moves: both arrows are drawn
  EXPECT_GT(f.motion.omega.length, 0.0);
  // The control: another frame's numbers differ.
  const json other = json::parse(world_frame_json(loop, drifting_panel(12)));
  EXPECT_NE(other["plane_corners"], out["plane_corners"]);
}

// A scene source's world: the loop's polygons and path and the frame's viewer matrix and
// colours are the teaching layer's scene world, to the bit.
TEST(WorldJson, SceneIsTheTeachingLayersSceneWorld) {
  auto scene = std::make_shared<const Scene>(read_scene_file(resolve_scene_path("street")));
  const ViewerScript walk = read_viewer_script_file(resolve_viewer_script_path("walk"));
  const auto animator = make_scene_animator(scene, walk, SceneSettings{});
  const double dt = PlanePanel::kSecondsPerFrame;
  const SceneWorldLoop loop = scene_world_loop(*animator, dt);
  const json out = json::parse(scene_world_loop_json(loop));
  EXPECT_EQ(out["kind"], "scene");
  ASSERT_EQ(out["outlines"].size(), loop.outlines.size());
  for (size_t k = 0; k < loop.outlines[0].size(); ++k)
    expect_point(out["outlines"][0][k], loop.outlines[0][k], "outline");
  ASSERT_EQ(out["path"].size(), loop.path.size());
  expect_point(out["path"][5], loop.path[5], "path");
  EXPECT_EQ(out["caption"].get<std::string>(), scene_world_caption(false));
  animator->start();
  for (int k = 0; k < 4; ++k) animator->advance();
  const SceneWorldFrame f = scene_world_frame(loop, *animator, dt);
  const json frame = json::parse(scene_world_frame_json(loop, *animator, dt));
  EXPECT_EQ(frame["frame"].get<int>(), 4);
  for (size_t i = 0; i < 16; ++i)
    EXPECT_EQ(frame["viewer_matrix"][i].get<double>(), f.viewer_matrix[i]) << i;
  ASSERT_EQ(frame["polygon_colours"].size(), f.colours.size());
  for (size_t k = 0; k < f.colours.size(); ++k)
    EXPECT_EQ(frame["polygon_colours"][k][0].get<int>(), int(f.colours[k].r)) << k;
  EXPECT_EQ(frame["arrows"]["normal"]["length"].get<double>(), 0.0);  // no plane in a scene
  // The control: a later frame's eye is elsewhere.
  for (int k = 0; k < 10; ++k) animator->advance();
  const json later = json::parse(scene_world_frame_json(loop, *animator, dt));
  EXPECT_NE(later["viewer_matrix"], frame["viewer_matrix"]);
}

// The page's labels are the teaching layer's place_labels, read back from the JSON; a request
// not of its form is refused naming the field.
TEST(WorldJson, LabelsArePlacedByTheTeachingLayersRule) {
  const std::vector<Vec2> sizes = {{40, 20}, {110, 20}, {20, 20}};
  const std::vector<Vec2> anchors(sizes.size(), Vec2(200, 150));
  const std::vector<std::vector<Vec2>> avoid = {{{150, 40}, {260, 40}, {260, 140}, {150, 140}}};
  const std::vector<LabelBox> expected = place_labels(sizes, anchors, LabelBox{10, 10, 400, 300},
                                                      {LabelBox{10, 280, 390, 30}}, 6.0, avoid);
  const json answer = json::parse(placed_labels_json(R"({"sizes": [[40, 20], [110, 20], [20, 20]],
      "anchors": [[200, 150], [200, 150], [200, 150]], "area": [10, 10, 400, 300],
      "taken": [[10, 280, 390, 30]], "gap": 6,
      "avoid": [[[150, 40], [260, 40], [260, 140], [150, 140]]]})"));
  ASSERT_EQ(answer.size(), expected.size());
  for (size_t i = 0; i < expected.size(); ++i) {
    EXPECT_EQ(answer[i][0].get<double>(), expected[i].x) << i;
    EXPECT_EQ(answer[i][1].get<double>(), expected[i].y) << i;
    EXPECT_EQ(answer[i][2].get<double>(), expected[i].width) << i;
  }
  // Control: the three labels on one point were moved apart, not left on their first place.
  EXPECT_NE(answer[0], answer[1]);
  try {
    placed_labels_json(R"({"sizes": [[40, 20]], "anchors": [[1, 2, 3]], "area": [0, 0, 9, 9]})");
    ADD_FAILURE() << "a three-number anchor was taken";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("anchors"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace oflab::test

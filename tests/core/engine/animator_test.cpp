// The Animator contract (core/engine/animator.h) for every animator: the frame sequence,
// start() restarting, camera-sized images, level histograms that account for the layers,
// and each kind's own mapping checked against an independent count.
#include "engine/animator.h"

#include <gtest/gtest.h>

#include <functional>
#include <memory>

#include "image/image_compare.h"
#include "scene/scene_animator.h"
#include "scene_cases.h"
#include "scene_shifting/scene_shifting_renderer.h"

namespace oflab {
namespace {

using testing::checker_image;
using testing::open_cube;
using testing::scene_with;
using testing::square;

// A plane that comes towards the viewer and passes it: visible first, then not.
MotionScript approaching_plane() {
  MotionScript script;
  script.camera = make_camera(300.0, 240, 180);
  PlanePose start;
  start.point = Vec3(0.1, 0.0, 2.0);
  start.normal = glm::normalize(Vec3(0.2, 0.1, 1.0));
  start.size = Vec2(1.0, 1.0);
  start.texture_size = glm::ivec2(64, 64);
  ScriptSegment segment;
  segment.frames = 12;
  segment.velocity = Vec3(0.0, 0.0, -0.25);
  segment.omega = Vec3(0.0, 0.01, 0.0);
  script.frames = expand_segments(start, MotionModel::kScrew, {segment});
  return script;
}

ViewerScript walk(const ViewerPose& start, const Vec3& velocity, const Vec3& omega, int frames) {
  ViewerScript script;
  script.camera = make_camera(300.0, 240, 180);
  script.frames = expand_viewer_segments(start, {ViewerSegment{frames, velocity, omega}});
  return script;
}

std::shared_ptr<const Scene> cubes() {
  std::vector<ScenePolygon> polygons = open_cube("a", Vec3(-0.8, 0, 0), 1.0);
  for (ScenePolygon& p : open_cube("b", Vec3(0.9, 0.2, -1.2), 1.0)) polygons.push_back(p);
  return std::make_shared<const Scene>(scene_with(polygons));
}

// Planes parallel to the image plane of a viewer at the origin looking along world -Z.
std::shared_ptr<const Scene> train_like() {
  const Vec3 front(0.0, 0.0, 1.0), up(0.0, 1.0, 0.0);
  return std::make_shared<const Scene>(
      scene_with({square("far", {0.5, 0.1, -20.0}, front, up, 12.0),
                  square("middle", {0.3, -0.2, -6.0}, front, up, 3.0),
                  square("bush-a", {-0.3, 0.2, -2.0}, front, up, 0.6),
                  square("bush-b", {0.4, 0.1, -2.4}, front, up, 0.6)}));
}

ViewerPose facing_minus_z() { return look_at({0, 0, 0}, {0, 0, -1}, {0, 1, 0}); }

std::vector<AnimationFrame> play_all(Animator& a) {
  std::vector<AnimationFrame> frames = {a.start()};
  while (a.frame() < a.frame_count() - 1) frames.push_back(a.advance());
  return frames;
}

// What every animator promises, checked over a whole run and a restart.
void expect_contract(Animator& a) {
  EXPECT_EQ(a.frame(), -1);
  ASSERT_GE(a.frame_count(), 2);
  const AnimationFrame first = a.start();
  const Image first_image = a.image();
  for (int k = 0; k < a.frame_count(); ++k) {
    const AnimationFrame f = k == 0 ? first : a.advance();
    EXPECT_EQ(a.frame(), k);
    EXPECT_EQ(f.frame, k);
    EXPECT_EQ(a.image().width(), a.camera().width);
    EXPECT_EQ(a.image().height(), a.camera().height);
    EXPECT_LE(f.drawn() + f.culled() + f.hidden, f.layers) << "frame " << k;
    EXPECT_LE(a.outlines().size(), static_cast<std::size_t>(f.drawn())) << "frame " << k;
    EXPECT_GE(f.max_measured_error_px, 0.0);
  }
  const AnimationFrame again = a.start();
  EXPECT_EQ(a.frame(), 0);
  EXPECT_EQ(again.levels, first.levels);
  EXPECT_EQ(again.pixels_written, first.pixels_written);
  EXPECT_EQ(a.image().pixels(), first_image.pixels());
}

TEST(Animator, PlaneAnimatorHonoursTheContract) {
  const MotionScript script = approaching_plane();
  auto a = make_plane_animator(script, checker_image(64, 64), EngineSettings{});
  EXPECT_EQ(a->frame_count(), 12);
  expect_contract(*a);
}

TEST(Animator, PlaneAnimatorReportsOneLayerWithItsEngineReport) {
  const MotionScript script = approaching_plane();
  auto a = make_plane_animator(script, checker_image(64, 64), EngineSettings{});
  int visible = 0, invisible = 0;
  for (const AnimationFrame& f : play_all(*a)) {
    EXPECT_EQ(f.layers, 1);
    ASSERT_EQ(f.layer_reports.size(), 1u);
    const FrameReport& r = f.layer_reports[0];
    EXPECT_EQ(f.drawn(), r.visible ? 1 : 0);
    if (r.visible) {
      EXPECT_EQ(f.levels[static_cast<int>(r.level)], 1);
    }
    EXPECT_EQ(f.pixels_written, r.pixels_written);
    EXPECT_EQ(f.note, r.note);
    (r.visible ? visible : invisible) += 1;
  }
  EXPECT_GT(visible, 0);
  EXPECT_GT(invisible, 0);  // the plane passes the viewer: nothing is drawn then
  // ... and the frame shown is then empty.
  for (const Pixel& p : a->image().pixels()) ASSERT_EQ(p.a, 0);
}

TEST(Animator, PlaneSeenAsASceneFromItsViewIsThePoseOfTheFrame) {
  const MotionScript script = approaching_plane();
  auto a = make_plane_animator(script, checker_image(64, 64), EngineSettings{});
  a->start();
  for (int k = 0; k < 6; ++k) {
    if (k > 0) a->advance();
    const PlanePose want = script.frames[static_cast<std::size_t>(k)].pose;
    const PlanePose got = polygon_pose(a->scene().polygons.at(0), a->view(), want.texture_size);
    EXPECT_LT(glm::length(got.point - want.point), 1e-9) << k;
    EXPECT_LT(glm::length(got.normal - glm::normalize(want.normal)), 1e-9) << k;
    EXPECT_NEAR(glm::dot(got.up, plane_axes(want).up), 1.0, 1e-9) << k;
  }
}

// The plane seen as a scene carries the engine's content, so re-rendering that scene from
// the animator's view (as the GUI's exact panel does) draws each content as the engine's own
// re-render of the pose does: the same lit image, not the bare texture.
TEST(Animator, PlaneSeenAsASceneDrawsTheEnginesContent) {
  const MotionScript script = approaching_plane();
  for (ContentKind kind : {ContentKind::kTexture, ContentKind::kShaded, ContentKind::kImpostor}) {
    EngineSettings settings;
    settings.policy = &reuse_policy("rerender");
    settings.content.kind = kind;
    auto a = make_plane_animator(script, checker_image(64, 64), settings);
    a->start();
    for (int k = 0; k < 3; ++k) a->advance();
    ASSERT_EQ(a->scene().polygons.at(0).content, kind);
    SceneSettings scene_settings;
    scene_settings.engine = settings;
    SceneEngine exact(a->scene(), a->camera(), scene_settings);
    exact.start(a->view());
    // Equal up to the last bits of the pose rebuilt from the view (a texel choice at a tie).
    EXPECT_GT(psnr_db(a->image(), exact.frame()), 40.0) << content_name(kind);
  }
}

TEST(Animator, SceneAnimatorHonoursTheContract) {
  auto a = make_scene_animator(
      cubes(),
      walk(look_at({0.5, 1.0, 5.0}, {0, 0, 0}, {0, 1, 0}), {0.05, 0.0, 0.05}, {0.0, 0.02, 0.0}, 10),
      SceneSettings{});
  expect_contract(*a);
}

TEST(Animator, SceneAnimatorAccountsForEveryPolygonAndReportsEachAnimatedOne) {
  auto a = make_scene_animator(
      cubes(),
      walk(look_at({0.5, 1.0, 5.0}, {0, 0, 0}, {0, 1, 0}), {0.05, 0.0, 0.05}, {0.0, 0.02, 0.0}, 10),
      SceneSettings{});
  for (const AnimationFrame& f : play_all(*a)) {
    EXPECT_EQ(f.layers, 10);
    EXPECT_EQ(f.drawn() + f.culled() + f.hidden, f.layers);
    int animated = 0;
    for (PolygonStatus s : a->renderer().statuses()) animated += s == PolygonStatus::kAnimated;
    EXPECT_EQ(static_cast<int>(f.layer_reports.size()), animated);
    EXPECT_EQ(f.drawn(), animated + f.clipped);
  }
}

TEST(Animator, SceneShiftingAnimatorHonoursTheContract) {
  auto a = make_scene_shifting_animator(
      train_like(), walk(facing_minus_z(), {0.03, 0.0, 0.0}, {0.0, 0.0, 0.0}, 12),
      SceneShiftingSettings{});
  expect_contract(*a);
}

// Independent of the renderer's own mapping: still = none, shifted = translate,
// scaled = affine, rebuilt = rerender, once per polygon drawn at its slice's last build.
std::array<int, kLevelCount> count_from_slice_updates(const SceneShiftingRenderer& r, int n) {
  const Level of[] = {Level::kNone, Level::kTranslate, Level::kAffine, Level::kRerender};
  std::array<int, kLevelCount> levels{};
  for (int p = 0; p < n; ++p) {
    const int slice = r.polygon_slices()[static_cast<std::size_t>(p)];
    if (slice < 0 || r.shown_corners(p).empty()) continue;
    const LayerUpdate u = r.slice_report().updates[static_cast<std::size_t>(slice)];
    ++levels[static_cast<int>(of[static_cast<int>(u)])];
  }
  return levels;
}

TEST(Animator, SceneShiftingLevelsCountEachPolygonAtItsSliceUpdate) {
  // Sideways, then forward (scaling), then a turn (every slice rebuilt).
  ViewerScript script = walk(facing_minus_z(), {0.03, 0.0, 0.0}, {0.0, 0.0, 0.0}, 8);
  const std::vector<ViewerFrame> more = expand_viewer_segments(
      script.frames.back().pose,
      {ViewerSegment{6, {0.0, 0.0, 0.05}, {0.0, 0.0, 0.0}}, ViewerSegment{4, {}, {0, 0.01, 0}}});
  script.frames.back().motion = more.front().motion;
  script.frames.insert(script.frames.end(), more.begin() + 1, more.end());
  auto a = make_scene_shifting_animator(train_like(), script, SceneShiftingSettings{});
  const int n = 4;
  std::array<int, kLevelCount> seen{};
  for (int k = 0; k < a->frame_count(); ++k) {
    const AnimationFrame f = k == 0 ? a->start() : a->advance();
    EXPECT_EQ(f.levels, count_from_slice_updates(a->renderer(), n)) << "frame " << k;
    EXPECT_EQ(f.drawn() + f.outside_frustum, n);
    EXPECT_EQ(a->outlines().size(), static_cast<std::size_t>(f.drawn()));
    EXPECT_TRUE(f.layer_reports.empty());
    for (int l = 0; l < kLevelCount; ++l) seen[l] += f.levels[l];
  }
  EXPECT_GT(seen[static_cast<int>(Level::kTranslate)], 0);
  EXPECT_GT(seen[static_cast<int>(Level::kRerender)], n);
  EXPECT_GT(a->renderer().totals().turning_frames, 0);
}

}  // namespace
}  // namespace oflab

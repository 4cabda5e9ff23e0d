// Today's reprojection in the animation view: the Reprojection menu's cadence and
// stabilization plane reach the engine (a cadence out of limits::kCadence is refused and the
// menu shows the engine's again), the stabilized-plane panel says which plane it warps by,
// the depth-reprojection heat map marks its holes, and the lesson claims that measure them
// (hole_pixels, hole_map_pixels, near_far_error) hold where they should and fail where they
// must (negative controls).
#include <QComboBox>
#include <QSpinBox>
#include <algorithm>
#include <cmath>

#include "adapters/frame_images.h"
#include "adapters/hole_map.h"
#include "app/lesson_check.h"
#include "models/animation_model.h"
#include "player/policy_comparison.h"
#include "runs/frame_maps.h"
#include "views/animation_view.h"
#include "views/number_box.h"
#include "views/reprojection_controls.h"
#include "window_fixture.h"

namespace oflab::test {
namespace {

class ReprojectionViewTest : public AnimationWindowTest {
 protected:
  // The comparison of `policies` on four cubes seen by `viewer`, played `frames` frames.
  void compare(const std::vector<std::string>& policies, const std::string& viewer, int frames) {
    window().show_view("animation");
    window().set_external_clock(true);
    ASSERT_TRUE(model().set_source({"scene", "four-cubes", viewer}));
    ASSERT_TRUE(window().model()->set_compared(policies));
    window().model()->set_panel_display(PanelDisplay::kComparison);
    window().play_frames(frames);
    animation().render_image();
  }

  double measure(const std::string& kind, const std::string& of) {
    LessonClaim claim;
    claim.claim = kind;
    claim.of = of;
    return measure_claim(&window(), claim);
  }
};

TEST_F(ReprojectionViewTest, CadenceAndPlaneOfTheMenuReachTheEngineAndOutOfRangeIsRefused) {
  window().show_view("animation");
  auto* cadence = animation().findChild<QSpinBox*>(QStringLiteral("animation_cadence"));
  auto* plane = animation().findChild<QComboBox*>(QStringLiteral("animation_stabilization"));
  auto* point_z =
      animation().findChild<NumberBox*>(QStringLiteral("animation_stabilization_point_2"));
  auto* button =
      animation().findChild<ReprojectionControls*>(QStringLiteral("animation_reprojection"));
  ASSERT_NE(cadence, nullptr);
  ASSERT_NE(plane, nullptr);
  ASSERT_NE(point_z, nullptr);
  ASSERT_NE(button, nullptr);
  EXPECT_EQ(cadence->value(), EngineSettings{}.cadence);
  EXPECT_FALSE(point_z->isEnabled());  // automatic fit: no point to give
  cadence->setValue(4);
  QApplication::processEvents();
  EXPECT_EQ(model().settings().cadence, 4);
  EXPECT_TRUE(button->toolTip().contains(QStringLiteral("every 4th frame")))
      << button->toolTip().toStdString();
  plane->setCurrentIndex(1);
  emit plane->activated(1);
  QApplication::processEvents();
  EXPECT_TRUE(point_z->isEnabled());
  point_z->setValue(-1.25);
  QApplication::processEvents();
  EXPECT_FALSE(model().settings().stabilization.automatic);
  EXPECT_DOUBLE_EQ(model().settings().stabilization.point.z, -1.25);
  EXPECT_TRUE(button->toolTip().contains(QStringLiteral("plane through (0, 0, -1.25)")));
  // One rule per value: 9 is outside limits::kCadence; the engine keeps 4 and the menu shows it.
  cadence->setValue(9);
  QApplication::processEvents();
  EXPECT_EQ(model().settings().cadence, 4);
  EXPECT_EQ(cadence->value(), 4);
}

TEST_F(ReprojectionViewTest, StabilizedPlanePanelSaysWhichPlaneItWarpsBy) {
  compare({"stabilized-plane", "cadence"}, "translate", 3);
  // The captions may be wrapped into lines: search them joined.
  const auto has = [&](const QString& words) {
    QString all;
    for (const PaintedText& t : animation().painted_texts()) all += t.text + QLatin1Char(' ');
    return all.simplified().contains(words);
  };
  EXPECT_TRUE(has(QStringLiteral("plane: automatic fit to the depth")));
  EngineSettings settings = model().settings();
  settings.stabilization = {false, Vec3(0.0, 0.0, 1.25), Vec3(0.0, 0.0, 1.0)};
  ASSERT_TRUE(model().set_settings(settings));
  animation().render_image();
  EXPECT_TRUE(has(QStringLiteral("plane through (0, 0, 1.25),")));
  EXPECT_TRUE(has(QStringLiteral("normal (0, 0, 1)")));
  EXPECT_FALSE(has(QStringLiteral("automatic fit")));
}

TEST_F(ReprojectionViewTest, HoleMapMarksTheDepthReprojectionsHolesAndOnlyThose) {
  compare({"depth-reprojection", "cadence"}, "translate", 15);  // frame 15: warped, holes
  const double holes = measure("hole_pixels", "depth-reprojection");
  const double marked = measure("hole_map_pixels", "");
  ASSERT_GT(holes, 0.0);
  // The map marks the pixels core counts (its depth test against the exact frame's coverage:
  // the same surfaces, so the same pixels up to texels the exact render leaves transparent).
  EXPECT_NEAR(marked, holes, 0.05 * holes);
  // An independent count: unreached pixels of the reprojection where the exact frame shows
  // something, through the adapter the view uses.
  const ComparedRun& run = window().model()->comparison().runs().front();
  const std::vector<std::uint8_t> mask =
      reprojection_hole_map(*run.animator(), animation().exact_image());
  EXPECT_EQ(double(std::count(mask.begin(), mask.end(), 1)), marked);
  // Negative controls: the cadence policy warps whole layers and has no holes, an unknown
  // policy is not measured, and a claim of holes on cadence does not hold.
  EXPECT_EQ(measure("hole_pixels", "cadence"), 0.0);
  EXPECT_TRUE(std::isnan(measure("hole_pixels", "talisman")));
  LessonClaim false_claim;
  false_claim.claim = "hole_pixels";
  false_claim.of = "cadence";
  false_claim.at_least = 1;
  const double measured = measure_claim(&window(), false_claim);
  EXPECT_FALSE(measured >= false_claim.at_least);
  // A rendered frame (a multiple of the cadence) is no reprojection: no hole map.
  window().play_frames(1);
  animation().render_image();
  EXPECT_EQ(animation().hole_map_pixels(), 0);
}

TEST_F(ReprojectionViewTest, HolesMarkedFromTheSourcesAreTheMasksHoles) {
  compare({"depth-reprojection", "cadence"}, "translate", 15);  // frame 15: warped, holes
  const ComparedRun& run = window().model()->comparison().runs().front();
  const Image& exact = animation().exact_image();
  const QImage unmarked = difference_map(run.animator()->image(), exact, 128);
  // The mask's way (a byte per pixel, then one pass on the window's thread) ...
  QImage by_mask = unmarked.copy();
  const std::int64_t mask_count =
      mark_holes(by_mask, reprojection_hole_map(*run.animator(), exact));
  // ... and the sources' way, in bands: the same pixels and count.
  const std::vector<int>* sources = reprojection_sources(*run.animator(), exact);
  ASSERT_NE(sources, nullptr);
  QImage by_sources = unmarked.copy();
  EXPECT_EQ(mark_reprojection_holes(by_sources, *sources, exact), mask_count);
  EXPECT_TRUE(by_sources == by_mask);
  EXPECT_EQ(animation().hole_map_pixels(), mask_count);
  // Controls: there are holes, so the marks changed the map; the cadence policy has no
  // sources; a map of another size is left alone.
  ASSERT_GT(mask_count, 0);
  EXPECT_FALSE(by_sources == unmarked);
  EXPECT_EQ(reprojection_sources(*window().model()->comparison().runs()[1].animator(), exact),
            nullptr);
  QImage small(8, 8, QImage::Format_RGB32);
  small.fill(Qt::black);
  EXPECT_EQ(mark_reprojection_holes(small, *sources, exact), 0);
}

TEST_F(ReprojectionViewTest, AFrameAlreadyOnScreenIsNotMappedAgain) {
  compare({"depth-reprojection", "cadence"}, "translate", 15);
  const int passes = animation().map_passes();
  const QImage first = animation().render_image();
  const std::int64_t holes = animation().hole_map_pixels();
  // The same frame drawn again: no map computed, the same picture and hole count.
  const QImage again = animation().render_image();
  EXPECT_EQ(animation().map_passes(), passes);
  EXPECT_TRUE(again == first);
  EXPECT_EQ(animation().hole_map_pixels(), holes);
  // Control: the next frame maps both runs again.
  window().play_frames(1);
  animation().render_image();
  EXPECT_EQ(animation().map_passes(), passes + 2);
  // Another policy in the comparison restarts the runs: both mapped again (once, whether the
  // change redraws the view itself or the render below does).
  const int before = animation().map_passes();
  ASSERT_TRUE(window().model()->set_compared({"depth-reprojection", "perspective"}));
  animation().render_image();
  EXPECT_EQ(animation().map_passes(), before + 2);
}

// The colours of `map` (RGB) that cover it, at most `most` of them counted.
int map_colours(const QImage& map, int most = 2) {
  std::vector<QRgb> seen;
  for (int y = 0; y < map.height(); ++y) {
    for (int x = 0; x < map.width(); ++x) {
      const QRgb c = map.pixel(x, y) & 0xffffffu;
      if (std::find(seen.begin(), seen.end(), c) == seen.end()) seen.push_back(c);
      if (int(seen.size()) >= most) return most;
    }
  }
  return int(seen.size());
}

// A compared re-render's frame is the exact panel's: its heat map compares the frame with itself
// and is the colour of no difference throughout, also where that map held another policy's map
// before (the comparison's order changed) and on the frames after, when it is not painted again.
// Control: the perspective policy's map has more than one colour.
TEST_F(ReprojectionViewTest, TheExactPanelsOwnHeatMapIsTheColourOfNoDifference) {
  compare({"perspective", "rerender"}, "translate", 10);
  const Image& frame = window().model()->comparison().runs()[1].animator()->image();
  const QRgb none = difference_map(frame, frame, 128).pixel(0, 0) & 0xffffffu;  // any scale: 0
  ASSERT_EQ(animation().heat_map(1).pixel(0, 0) & 0xffffffu, none);
  EXPECT_EQ(map_colours(animation().heat_map(1)), 1);
  EXPECT_EQ(map_colours(animation().heat_map(0)), 2);
  ASSERT_TRUE(window().model()->set_compared({"rerender", "perspective"}));
  animation().render_image();
  EXPECT_EQ(map_colours(animation().heat_map(0)), 1);
  EXPECT_EQ(animation().heat_map(0).pixel(7, 5) & 0xffffffu, none);
  EXPECT_EQ(map_colours(animation().heat_map(1)), 2);
  const int passes = animation().map_passes();
  window().play_frames(1);
  animation().render_image();
  EXPECT_EQ(animation().map_passes(), passes + 2);
  EXPECT_EQ(map_colours(animation().heat_map(0)), 1);
  EXPECT_EQ(animation().heat_map(0).pixel(0, 0) & 0xffffffu, none);
}

TEST_F(ReprojectionViewTest, TimewarpsErrorGrowsWithInverseDepthUnderTranslationOnly) {
  compare({"timewarp", "perspective"}, "translate", 31);
  const double ratio = measure("near_far_error", "timewarp");
  EXPECT_GT(ratio, 1.2);  // the near cubes slip further
  // Negative control: the claim that the far cubes err more fails.
  EXPECT_FALSE(ratio <= 1.0);
  // A roll moves every depth alike: timewarp is exact.
  compare({"timewarp", "perspective"}, "rotate", 31);
  const double rolled = measure("max_error", "timewarp");
  EXPECT_LE(rolled, 0.5);
}

}  // namespace
}  // namespace oflab::test

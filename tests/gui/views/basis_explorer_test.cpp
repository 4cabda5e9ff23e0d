// The basis explorer (session/basis/basis_explorer.h, gui/views/explorer_panel.h): its model
// against independent computations (the deformation against the flow integrated point by
// point, the grid's changes against hand formulas), the sliders driving the deformation, the
// lit tiles and the solutions panel in a real window, the two futures as the panel shows
// them, and the lesson claims of the explorer, each with a negative control.
#include "basis/basis_explorer.h"

#include <QDoubleSpinBox>
#include <QLabel>
#include <QPushButton>
#include <QSlider>
#include <algorithm>
#include <cmath>

#include "app/lesson_check.h"
#include "flow/homography.h"
#include "image_checks.h"
#include "models/scene_model.h"
#include "views/basis_tiles.h"
#include "views/basis_view.h"
#include "views/explorer_panel.h"
#include "views/explorer_pictures.h"
#include "views/image_canvas.h"
#include "views/slider_spin.h"
#include "window_fixture.h"

namespace oflab::test {
namespace {

const Camera kCamera = make_camera(600.0, 800, 600);

ExplorerTerms only(const char* key, double value) {
  ExplorerTerms terms{};
  terms[size_t(find_explorer_term(key))] = value;
  return terms;
}

// Where the flow carries point p in time t, by Runge-Kutta steps of core's flow_at
// (independent of the homography the explorer composes).
Vec2 integrate_flow(const PlanarFlowCoefficients& c, Vec2 p, double t) {
  constexpr int kSteps = 2000;
  const double h = t / kSteps;
  for (int k = 0; k < kSteps; ++k) {
    const Vec2 k1 = flow_at(c, p), k2 = flow_at(c, p + 0.5 * h * k1);
    const Vec2 k3 = flow_at(c, p + 0.5 * h * k2), k4 = flow_at(c, p + h * k3);
    p += h / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
  }
  return p;
}

TEST(BasisExplorer, TheDeformationIsWhereTheFlowCarriesEachPointInOneSecond) {
  const ExplorerTerms terms = default_explorer_terms();
  const PlanarFlowCoefficients c = explorer_coefficients(terms);
  const Mat3 h = explorer_deformation(terms);
  for (const Vec2& p : {Vec2(0, 0), Vec2(-200, -150), Vec2(200, -150), Vec2(120, 150)}) {
    const Vec2 want = integrate_flow(c, p, kDeformationSeconds);
    EXPECT_LT(glm::length(apply_homography(h, p) - want), 0.05) << p.x << " " << p.y;
  }
  // Control: the first-order homography over the whole second is visibly off.
  const Vec2 corner(200, -150);
  EXPECT_GT(glm::length(apply_homography(taylor_homography(c, 1.0), corner) -
                        integrate_flow(c, corner, 1.0)),
            1.0);
}

TEST(BasisExplorer, EachTermAloneChangesTheGridAsItsNameSays) {
  const GridChange shift = explorer_grid_change(only("tx", 50.0), kCamera);
  EXPECT_NEAR(shift.shift_px, 50.0, 1e-6);
  EXPECT_NEAR(shift.area, 1.0, 1e-9);
  const GridChange scale = explorer_grid_change(only("scale", 0.2), kCamera);
  EXPECT_NEAR(scale.area, std::exp(0.4), 1e-3);  // both axes grow by e^0.2
  const GridChange squash = explorer_grid_change(only("squash", 0.2), kCamera);
  EXPECT_NEAR(squash.area, 1.0, 1e-3);
  const GridChange turn = explorer_grid_change(only("rotation", 0.3), kCamera);
  EXPECT_NEAR(turn.turn_deg, 0.3 * 180.0 / M_PI, 0.02);
  EXPECT_NEAR(turn.keystone, 0.0, 1e-9);
  EXPECT_GT(explorer_grid_change(only("px", 0.0002), kCamera).keystone, 0.05);
  // The terms' symbols are the planar gallery's, in its order.
  const std::vector<BasisTerm> gallery = basis_terms(BasisKind::kPlanar);
  for (const ExplorerTerm& term : explorer_terms()) {
    const auto same = [&](const BasisTerm& t) { return t.symbol == term.key; };
    EXPECT_NE(std::find_if(gallery.begin(), gallery.end(), same), gallery.end()) << term.key;
  }
}

TEST(BasisExplorer, TheStartingValuesHaveTwoWorldsThatPartAtFrame13) {
  const ExplorerResult r = explore(default_explorer_terms(), kCamera);
  ASSERT_EQ(r.inverse.solutions.size(), 2u);
  ASSERT_TRUE(r.futures_played);
  EXPECT_LT(r.futures.corner_distance_px[1], 0.01);  // the same flow: apart at second order
  EXPECT_EQ(r.futures.first_frame_apart, 13);
  EXPECT_LE(r.futures.corner_distance_px[12], 1.0);
  EXPECT_GT(r.futures.corner_distance_px[13], 1.0);
  // Each solution maps forward to the dialled coefficients (core's own check, here on the
  // explorer's numbers).
  for (const PlanarMotionSolution& s : r.inverse.solutions) {
    const SolutionScene scene =
        solution_scene(s, kCamera.focal_px, Vec2(0, 0), MotionModel::kScrew);
    const PlanarFlowCoefficients back = planar_flow_coefficients(kCamera, scene.pose, scene.motion);
    EXPECT_LT(relative_coefficient_difference(back, r.coefficients, kCamera.focal_px), 1e-9);
  }
}

TEST(BasisExplorer, TheSketchIsTheUnitSquareSeenFromTheFixedView) {
  // The fixed view turns 0.9 rad about Y, then tilts 0.45 rad about X, orthographic: the Y
  // axis keeps x = 0 and shortens by cos 0.45; a point on X turns into x = cos 0.9 and is
  // tilted by sin 0.45 sin 0.9.
  EXPECT_NEAR(explorer_view_of(Vec3(0, 1, 0)).x, 0.0, 1e-15);
  EXPECT_NEAR(explorer_view_of(Vec3(0, 1, 0)).y, std::cos(0.45), 1e-15);
  EXPECT_NEAR(explorer_view_of(Vec3(1, 0, 0)).x, std::cos(0.9), 1e-15);
  EXPECT_NEAR(explorer_view_of(Vec3(1, 0, 0)).y, std::sin(0.45) * std::sin(0.9), 1e-15);
  const ExplorerResult r = explore(default_explorer_terms(), kCamera);
  ASSERT_EQ(r.inverse.solutions.size(), 2u);
  const double arrow = explorer_arrow_scale(r.inverse.solutions);
  double longest = 0.0;
  for (const PlanarMotionSolution& s : r.inverse.solutions) {
    longest = std::max({longest, glm::length(s.v_over_d), glm::length(s.omega)});
    // A square seen orthographically is a parallelogram about its centre.
    const SolutionSketch k = explorer_sketch(s, arrow);
    const Vec2 mean = 0.25 * (k.corners[0] + k.corners[1] + k.corners[2] + k.corners[3]);
    EXPECT_LT(glm::length(k.corners[0] + k.corners[2] - k.corners[1] - k.corners[3]), 1e-12);
    EXPECT_LT(glm::length(mean - k.centre), 1e-12);
    EXPECT_LT(glm::length(k.spin_tip - explorer_view_of(arrow * s.omega)), 1e-15);
  }
  EXPECT_NEAR(arrow * longest, 0.8, 1e-12);
  EXPECT_EQ(explorer_case_text(r.inverse).rfind("General case: two planes", 0), 0u);
  EXPECT_EQ(explorer_case_text(explore(ExplorerTerms{}, kCamera).inverse).rfind("No motion", 0),
            0u);
  PlanarMotionSolution facing;
  facing.normal = Vec3(0, 0, 1);
  EXPECT_EQ(explorer_facing_text(facing), "faces it squarely");
  facing.normal = Vec3(std::sin(0.5), 0, std::cos(0.5));  // 28.6 degrees
  EXPECT_EQ(explorer_facing_text(facing), "turned 29\u00b0 away");
}

class BasisExplorerWindow : public WindowTest {
 protected:
  void SetUp() override {
    WindowTest::SetUp();
    window().set_external_clock(true);
    window().model()->set_view("basis");
    window().model()->set_basis_explorer(true);
    QApplication::processEvents();
  }
  BasisView& basis() { return *view_page<BasisView>(window(), "basis"); }
  ExplorerPanel& panel() { return *basis().explorer(); }
  double measure(const char* kind, const char* of = "") {
    LessonClaim claim;
    claim.claim = kind;
    claim.of = of;
    return measure_claim(&window(), claim);
  }
};

TEST_F(BasisExplorerWindow, SlidersDriveTheDeformationTheTilesAndTheSolutions) {
  ASSERT_TRUE(window().model()->set_explorer_terms(ExplorerTerms{}));
  basis().render_image();
  EXPECT_EQ(basis().active_tile_count(), 0);
  const QImage still = panel().deformation()->image();
  EXPECT_NE(panel().solutions_text().indexOf("No motion"), -1)
      << panel().solutions_text().toStdString();
  // Type 0.2 into the scale slider's field, as a user does.
  SliderSpin* scale = panel().slider(find_explorer_term("scale"));
  ASSERT_NE(scale, nullptr);
  scale->spin_box()->setValue(0.2);
  QApplication::processEvents();
  EXPECT_DOUBLE_EQ(window().model()->explorer_terms()[2], 0.2);
  basis().render_image();
  EXPECT_EQ(basis().active_tile_count(), 1);
  EXPECT_EQ(basis().tile_active("scale"), 1.0);
  EXPECT_EQ(basis().tile_active("rotation"), 0.0);
  const QImage grown = panel().deformation()->image();
  ASSERT_EQ(grown.size(), still.size());  // the layout does not move while a slider does
  // The picture zooms on what it shows: the grown grid fills it as the still one did, and the
  // dashed start shrinks inside it.
  EXPECT_GT(changed_fraction(grown, still), 0.02);
  EXPECT_NE(panel().solutions_text().indexOf("fronto-parallel"), -1)
      << panel().solutions_text().toStdString();
  // Then rotation by its slider: a second tile, and the default case comes back with all.
  panel().slider(find_explorer_term("rotation"))->slider()->setValue(150);  // +0.5 1/s
  QApplication::processEvents();
  EXPECT_NEAR(window().model()->explorer_terms()[5], 0.5, 1e-12);
  basis().render_image();
  EXPECT_EQ(basis().active_tile_count(), 2);
  ASSERT_TRUE(window().model()->set_explorer_terms(default_explorer_terms()));
  QApplication::processEvents();
  EXPECT_EQ(panel().result().inverse.solutions.size(), 2u);
  EXPECT_NE(panel().solutions_text().indexOf("two planes"), -1);
  EXPECT_EQ(panel().slider(0)->value(), 40.0);  // the sliders follow the model
  // A value beyond its limit is refused and the field shows the kept value.
  scale->spin_box()->setValue(500.0);
  QApplication::processEvents();
  EXPECT_EQ(window().model()->explorer_terms()[2], default_explorer_terms()[2]);
  EXPECT_NEAR(scale->value(), default_explorer_terms()[2], 1e-9);
}

TEST_F(BasisExplorerWindow, FromTheSceneCopiesTheScenesFlowAndAllZeroClearsIt) {
  auto* from_scene = basis().findChild<QPushButton*>(QStringLiteral("explorer_from_scene"));
  auto* zero = basis().findChild<QPushButton*>(QStringLiteral("explorer_zero"));
  ASSERT_NE(from_scene, nullptr);
  ASSERT_NE(zero, nullptr);
  from_scene->click();
  QApplication::processEvents();
  const SceneModel& scene = *window().model()->scene();
  const PlanarFlowCoefficients want =
      planar_flow_coefficients(scene.scene().camera, scene.current_pose(), scene.current_motion());
  // The dialled terms make the scene's own eight coefficients back.
  const PlanarFlowCoefficients got = explorer_coefficients(window().model()->explorer_terms());
  EXPECT_LT(relative_coefficient_difference(got, want, scene.scene().camera.focal_px), 1e-12);
  zero->click();
  QApplication::processEvents();
  EXPECT_EQ(window().model()->explorer_terms(), ExplorerTerms{});
  EXPECT_EQ(basis().active_tile_count(), 0);
}

TEST_F(BasisExplorerWindow, TheFuturesAgreeAtFirstAndPartAtTheFrameThePanelShows) {
  ASSERT_TRUE(window().model()->set_explorer_terms(default_explorer_terms()));
  QApplication::processEvents();
  const ExplorerResult& r = panel().result();
  ASSERT_TRUE(r.futures_played);
  EXPECT_LT(r.futures.corner_distance_px[1], 0.01);
  EXPECT_NE(panel().futures_text().indexOf("over 1 px first at frame 13"), -1)
      << panel().futures_text().toStdString();
  // Play: frame by frame from 0 to the end, each line naming that frame's distance.
  auto* play = basis().findChild<QPushButton*>(QStringLiteral("explorer_play_futures"));
  ASSERT_NE(play, nullptr);
  play->click();
  EXPECT_TRUE(panel().futures_playing());
  EXPECT_EQ(panel().futures_frame(), 0);
  const QImage start = panel().worlds()->grab().toImage();  // frame 0: the curve not yet drawn
  for (int k = 1; k <= kFutureFrames; ++k) {
    basis().step_animation();
    EXPECT_EQ(panel().futures_frame(), k);
  }
  EXPECT_FALSE(panel().futures_playing());
  EXPECT_NE(panel().futures_text().indexOf("Frame 30 of 30"), -1);
  EXPECT_GT(changed_fraction(panel().worlds()->grab().toImage(), start), 0.0);
  EXPECT_EQ(measure("futures_apart_frame"), 13.0);
  EXPECT_LT(measure("futures_first_px"), 0.01);
}

TEST_F(BasisExplorerWindow, TheExplorersClaimsMeasureWhatTheyNameWithControls) {
  ASSERT_TRUE(window().model()->set_explorer_terms(default_explorer_terms()));
  EXPECT_EQ(measure("solution_count"), 2.0);
  EXPECT_GT(measure("panel_fill"), 25.0);  // percent of the deformation picture
  ASSERT_TRUE(window().model()->set_explorer_terms(only("tx", 560.0)));
  EXPECT_LT(measure("panel_fill"), 10.0);  // control: the rectangle carried out of the image
  window().model()->set_basis_explorer(false);
  EXPECT_GT(measure("panel_fill"), 25.0);  // the gallery's smallest tile
  window().model()->set_basis_explorer(true);
  ASSERT_TRUE(window().model()->set_explorer_terms(only("scale", 0.2)));
  EXPECT_EQ(measure("solution_count"), 1.0);        // control: a degenerate case
  EXPECT_EQ(measure("futures_apart_frame"), -1.0);  // control: nothing to compare
  EXPECT_TRUE(std::isnan(measure("futures_first_px")));
  EXPECT_EQ(measure("tile_active", "scale"), 1.0);
  EXPECT_EQ(measure("tile_active", "tx"), 0.0);  // control: a term not dialled
  EXPECT_TRUE(std::isnan(measure("tile_active", "no-such-term")));
  EXPECT_NEAR(measure("grid_change", "area"), std::exp(0.4), 1e-3);
  EXPECT_NEAR(measure("grid_change", "shift_px"), 0.0, 1e-9);
  EXPECT_TRUE(std::isnan(measure("grid_change", "volume")));  // control: no such field
  ASSERT_TRUE(window().model()->set_explorer_terms(only("ty", -30.0)));
  EXPECT_NEAR(measure("grid_change", "shift_px"), 30.0, 1e-9);
  EXPECT_NEAR(measure("grid_change", "area"), 1.0, 1e-9);  // control: a shift keeps the area
  EXPECT_EQ(measure("tile_active", "scale"), 0.0);
}

// panel_fill of the explorer (explorer_deformation_fill) against the framing computed by hand:
// the texture rectangle (400 x 300 of an 800 x 600 image) grown by 3 % on every side fills the
// picture under the caption. The control: the rectangle carried 560 px right, of which only
// 40 x 300 px stay in the image; the framing holds the start and the part inside, and the
// fill falls under a tenth.
TEST(BasisFill, TheExplorersFillIsTheDeformedRectangleInsideTheImageOverItsPicture) {
  const ViewTheme theme = view_theme(false);
  const QSize size(700, 500);
  const DeformationFraming still = explorer_deformation_framing(Mat3(1.0), kCamera, size, theme);
  const double area = still.picture.width() * still.picture.height();
  const double scale = std::min(still.picture.width() / 424.0, still.picture.height() / 318.0);
  EXPECT_NEAR(still.scale, scale, 1e-9);
  EXPECT_NEAR(explorer_deformation_fill(Mat3(1.0), kCamera, size, theme),
              400.0 * 300.0 * scale * scale / area, 1e-6);
  Mat3 shift(1.0);
  shift[2][0] = 560.0;  // x + 560: the third column is the translation
  const DeformationFraming moved = explorer_deformation_framing(shift, kCamera, size, theme);
  // The start and the shifted rectangle span x -200 .. 760, grown by 28.8 px: -228.8 .. 788.8,
  // cut at the image's edge x = 400; y -159 .. 159.
  const double shifted = std::min(moved.picture.width() / 628.8, moved.picture.height() / 318.0);
  EXPECT_NEAR(moved.scale, shifted, 1e-9);
  const double fill = explorer_deformation_fill(shift, kCamera, size, theme);
  EXPECT_NEAR(fill, 40.0 * 300.0 * shifted * shifted / area, 1e-6);
  EXPECT_LT(fill, 0.1);
}

// panel_fill of the gallery (BasisTiles::smallest_fill): undeformed, every tile's square fills
// the cell's width but 4 % each side or its height but the title and value bands (1.25 title
// heights and 3 % of the cell each), whichever is less. Controls: nothing painted yet, a
// gallery too small for any grid (nothing drawn, nothing filled), and tiles framed for a
// larger amount than they show, which fill less.
TEST(BasisFill, TheGallerysFillIsTheSmallestDeformedSquareOverItsTile) {
  BasisTiles tiles;
  tiles.set_theme(view_theme(false));
  tiles.update(BasisKind::kPlanar, TaylorTerms{}, 400.0, 0.0, 0.0);
  EXPECT_EQ(tiles.smallest_fill(), 0.0);
  tiles.paint(QSize(600, 450));  // cells of 100 x 150
  const double band = 1.25 * tiles.title_font_size() + 0.03 * 150.0;
  const double half = std::min(0.46 * 100.0, 75.0 - band);
  const double fitted = 4.0 * half * half / (100.0 * 150.0);
  EXPECT_NEAR(tiles.smallest_fill(), fitted, 1e-9);
  tiles.update(BasisKind::kPlanar, TaylorTerms{}, 400.0, 0.0, 1.0);
  tiles.paint(QSize(600, 450));
  EXPECT_LT(tiles.smallest_fill(), 0.8 * fitted);
  tiles.paint(QSize(60, 30));
  EXPECT_EQ(tiles.smallest_fill(), 0.0);
}

// The explorer's texts at 1920 x 1080 and 1366 x 768 in presentation mode (scaled to the
// window), with the scene panel and without: none cut, none over another (cut_texts,
// ExplorerPanel::text_problems); the control is a window held smaller than its layout needs,
// which cuts some.
TEST_F(BasisExplorerWindow, EveryTextFitsAt1080pWithAndWithoutTheScenePanel) {
  window().model()->set_presentation(true);
  const auto problems = [this] {
    basis().render_image();
    QString all;
    for (const QString& p : basis().text_problems()) all += p + QStringLiteral("; ");
    return all.toStdString();
  };
  for (const QSize& size : {QSize(1920, 1080), QSize(1366, 768)}) {
    for (bool scene_panel : {true, false}) {
      window().model()->set_scene_panel(scene_panel);
      window().resize(size);
      QApplication::processEvents();
      EXPECT_EQ(measure("cut_texts"), 0.0)
          << size.width() << " x " << size.height() << (scene_panel ? " with" : " without")
          << " the scene panel: " << problems();
    }
  }
  window().model()->set_scene_panel(true);
  window().setFixedSize(900, 560);
  QApplication::processEvents();
  EXPECT_GT(measure("cut_texts"), 0.0);
}

// The two futures as two pictures side by side: the texture on each solution's quad in the
// upper half's left and right; the control, the same picture without a texture, has none.
TEST(BasisExplorer, TheFuturesShowAsTwoPicturesSideBySide) {
  const Camera camera = make_camera(600.0, 800, 600);
  const ExplorerResult r = explore(default_explorer_terms(), camera);
  ASSERT_TRUE(r.futures_played);
  QImage texture(64, 64, QImage::Format_RGB32);
  texture.fill(QColor(255, 0, 255));
  const ViewTheme theme = view_theme(false);
  const auto magenta_share = [](const QImage& image, const QRect& part) {
    int count = 0;
    for (int y = part.top(); y <= part.bottom(); ++y) {
      for (int x = part.left(); x <= part.right(); ++x) {
        count += image.pixel(x, y) == qRgb(255, 0, 255);
      }
    }
    return double(count) / double(part.width() * part.height());
  };
  const QSize size(600, 600);
  const QImage with = paint_explorer_futures(r, 15, texture, camera, size, theme);
  const QImage without = paint_explorer_futures(r, 15, QImage(), camera, size, theme);
  for (const QRect& half : {QRect(0, 0, 300, 300), QRect(300, 0, 300, 300)}) {
    EXPECT_GT(magenta_share(with, half), 0.03);
    EXPECT_EQ(magenta_share(without, half), 0.0);
  }
}

// In the window at 1920 x 1080 in presentation mode, with the scene panel shown and hidden,
// the explorer's worlds column runs down the whole body, so the futures' canvas is tall
// enough for the two pictures over the chart (14 label heights), and its texts stay whole;
// the canvas at the futures' last frame matches its baseline (scene panel hidden). The
// control: the same canvas painted without a texture (the two pictures empty) does not.
TEST_F(BasisExplorerWindow, TheFuturesShowAsTwoPicturesInTheWindowAt1080p) {
  window().model()->set_presentation(true);
  ASSERT_TRUE(window().model()->set_explorer_terms(default_explorer_terms()));
  auto* futures = basis().findChild<ImageCanvas*>(QStringLiteral("explorer_futures"));
  ASSERT_NE(futures, nullptr);
  for (bool scene_panel : {true, false}) {
    window().model()->set_scene_panel(scene_panel);
    window().resize(1920, 1080);
    QApplication::processEvents();
    basis().render_image();
    EXPECT_GE(futures->height(), 14.0 * panel().smallest_text_px())
        << (scene_panel ? "with" : "without") << " the scene panel: " << futures->height();
    EXPECT_EQ(measure("cut_texts"), 0.0) << (scene_panel ? "with" : "without");
  }
  const ExplorerResult& r = panel().result();
  ASSERT_TRUE(r.futures_played);
  EXPECT_EQ(panel().futures_frame(), r.futures.frames_played);
  const QImage shown = futures->image();
  test::expect_matches_baseline(shown, QStringLiteral("explorer-futures-presentation"), 480);
  const QImage baseline(QStringLiteral(OFLAB_GUI_BASELINES "/explorer-futures-presentation.png"));
  ASSERT_FALSE(baseline.isNull());
  const QImage empty = paint_explorer_futures(r, panel().futures_frame(), QImage(),
                                              window().model()->scene()->scene().camera,
                                              shown.size(), view_theme(true));
  EXPECT_LT(psnr_db(baseline, scaled_rgb(empty, baseline.size())), kBaselinePsnrDb)
      << "the control: the futures without their pictures' texture";
}

}  // namespace
}  // namespace oflab::test

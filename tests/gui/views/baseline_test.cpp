// Screenshot baselines of the views (tests/gui/baselines/*.png), compared with the
// tolerance documented in image_checks.h (PSNR >= 30 dB after scaling to the baseline's
// size). A failing or missing baseline writes the rendered image, scaled, to
// <build>/tests/gui/output/ and fails. To accept new images on purpose, run the tests with
// OFLAB_UPDATE_BASELINES=1: each baseline test then rewrites its PNG and reports itself as
// skipped, never as passed.
#include <QDir>
#include <QFileInfo>

#include "image_checks.h"
#include "views/animation_view.h"
#include "views/basis_view.h"
#include "views/flow_view.h"
#include "window_fixture.h"

namespace oflab::test {
namespace {

constexpr int kBaselineWidth = 320;

class BaselineTest : public WindowTest {
 protected:
  // Compares `rendered` with baselines/<name>.png (image_checks.h).
  void expect_matches_baseline(const QImage& rendered, const QString& name) {
    test::expect_matches_baseline(rendered, name, kBaselineWidth);
  }
};

TEST_F(BaselineTest, FlowViewOfTheDemoMatchesItsBaseline) {
  expect_matches_baseline(view_page<FlowView>(window(), "flow")->render_image(), "flow-demo");
}

TEST_F(BaselineTest, ToleranceCatchesAFlowViewWithoutArrows) {
  // The tolerance must not be so loose that a lost arrow field passes.
  const QImage baseline(QStringLiteral(OFLAB_GUI_BASELINES "/flow-demo.png"));
  ASSERT_FALSE(baseline.isNull()) << "missing baseline flow-demo.png";
  FlowDisplay d = view_page<FlowView>(window(), "flow")->display();
  d.arrows = false;
  window().model()->set_flow_display(d);
  const QImage rendered =
      scaled_rgb(view_page<FlowView>(window(), "flow")->render_image(), baseline.size());
  EXPECT_LT(psnr_db(baseline, rendered), kBaselinePsnrDb - 5.0);
}

TEST_F(BaselineTest, FlowViewSecondOrderWithColourWheelMatchesItsBaseline) {
  FlowDisplay d = view_page<FlowView>(window(), "flow")->display();
  d.part = FlowPart::kSecondOrder;
  d.colour_wheel = true;
  d.streamlines = true;
  window().model()->set_flow_display(d);
  expect_matches_baseline(view_page<FlowView>(window(), "flow")->render_image(),
                          "flow-second-order-wheel");
}

TEST_F(BaselineTest, PlanarBasisGalleryMatchesItsBaseline) {
  window().show_view("basis");
  QApplication::processEvents();
  window().model()->set_basis(BasisKind::kPlanar);
  expect_matches_baseline(view_page<BasisView>(window(), "basis")->render_image(), "basis-planar");
}

TEST_F(BaselineTest, AnimationViewOfTheDemoMatchesItsBaseline) {
  window().show_view("animation");
  window().set_external_clock(true);
  window().play_frames(10);
  expect_matches_baseline(view_page<AnimationView>(window(), "animation")->render_image(),
                          "animation-demo");
}

TEST_F(BaselineTest, AnimationViewDifferenceMatchesItsBaseline) {
  window().show_view("animation");
  window().set_external_clock(true);
  window().model()->set_panel_display(PanelDisplay::kDifference);
  window().play_frames(10);
  expect_matches_baseline(view_page<AnimationView>(window(), "animation")->render_image(),
                          "animation-difference");
}

TEST_F(BaselineTest, AnimationViewComparisonMatchesItsBaseline) {
  window().show_view("animation");
  window().set_external_clock(true);
  window().model()->set_panel_display(PanelDisplay::kComparison);
  window().play_frames(10);
  expect_matches_baseline(view_page<AnimationView>(window(), "animation")->render_image(),
                          "animation-comparison");
}

}  // namespace
}  // namespace oflab::test

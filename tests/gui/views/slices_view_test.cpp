// The scene-shifting view: it draws the train-window slices and the layered animation, and
// its sliders re-cut the slices (a larger epsilon gives fewer, wider slices).
#include "views/slices_view.h"

#include <QApplication>
#include <QDoubleSpinBox>

#include "adapters/frame_images.h"
#include "image_checks.h"
#include "models/scene_model.h"
#include "models/window_model.h"
#include "views/slider_spin.h"
#include "window_fixture.h"

namespace oflab::test {
namespace {

using SlicesViewTest = WindowTest;

TEST_F(SlicesViewTest, DrawsTheSlicesAndPlaysTheLayeredAnimation) {
  auto* view = dynamic_cast<SlicesView*>(window().view("slices"));
  ASSERT_NE(view, nullptr);
  ASSERT_TRUE(window().show_view("slices"));
  QApplication::processEvents();
  const QImage first = view->render_image();
  EXPECT_GT(first.width(), 400);
  EXPECT_GT(distinct_colours(first), 50);
  EXPECT_GT(view->slice_count(), 2);
  window().model()->scene()->set_frame(window().model()->scene()->frame() + 5);
  const QImage later = view->render_image();
  EXPECT_GT(changed_fraction(first, later), 0.001);  // the train moved on
}

TEST_F(SlicesViewTest, LargerEpsilonGivesFewerSlices) {
  auto* view = dynamic_cast<SlicesView*>(window().view("slices"));
  ASSERT_NE(view, nullptr);
  const int before = view->slice_count();
  auto* epsilon = view->findChildren<SliderSpin*>().front();
  epsilon->spin_box()->setValue(4.0);
  QApplication::processEvents();
  EXPECT_DOUBLE_EQ(view->epsilon_px(), 4.0);
  EXPECT_LT(view->slice_count(), before);
}

// The exact panel is core's exact projection of the same viewer frame: where scene shifting
// drew the scene, so did the exact render (slices moved as layers against every polygon
// warped exactly: two different renderings of one frame).
TEST_F(SlicesViewTest, ShowsTheExactProjectionOfTheSameFrame) {
  auto* view = dynamic_cast<SlicesView*>(window().view("slices"));
  ASSERT_NE(view, nullptr);
  ASSERT_TRUE(window().show_view("slices"));
  window().model()->scene()->set_frame(window().model()->scene()->frame() + 4);
  view->render_image();
  const Image& exact = view->exact_image();
  const Image& shifted = view->shifted_image();
  ASSERT_FALSE(exact.empty());
  ASSERT_EQ(exact.width(), shifted.width());
  ASSERT_EQ(exact.height(), shifted.height());
  const FrameAgreement agreement = frame_agreement(shifted, exact);
  EXPECT_GT(agreement.mask_iou, 0.9);
  EXPECT_GT(agreement.psnr_db, 15.0);
}

// The one frame counter (issue: the view ignored Step, Back, Home and End): the window's
// step, back and home move the slices, and its frame is the window's.
TEST_F(WindowTest, SlicesFollowTheWindowsFrameCounter) {
  window().show_view("slices");
  auto* view = dynamic_cast<SlicesView*>(window().view("slices"));
  ASSERT_NE(view, nullptr);
  SceneModel* scene = window().model()->scene();
  scene->set_frame(7);
  EXPECT_EQ(view->frame(), 7);
  const QImage at_seven = view->render_image();
  scene->advance(1);  // Step
  EXPECT_EQ(view->frame(), 8);
  scene->set_frame(7);  // Back
  EXPECT_EQ(view->frame(), 7);
  EXPECT_EQ(view->render_image(), at_seven);  // the same picture as on the way forward
  scene->set_frame(0);                        // Home
  EXPECT_EQ(view->frame(), 0);
  window().play_frames(3);
  EXPECT_EQ(view->frame(), scene->frame());
}

// The walk (120 frames) is shorter than the window's loop (150): past its end the view
// shows the walk's frame and its caption names the play bar's frame it stands for.
TEST_F(WindowTest, SlicesCaptionSaysWhenTheWalkRepeats) {
  window().show_view("slices");
  auto* view = dynamic_cast<SlicesView*>(window().view("slices"));
  ASSERT_NE(view, nullptr);
  SceneModel* scene = window().model()->scene();
  ASSERT_GT(scene->loop_frames(), 140);
  scene->set_frame(20);
  view->render_image();
  EXPECT_FALSE(view->caption().contains("repeats")) << view->caption().toStdString();
  scene->set_frame(140);
  view->render_image();
  EXPECT_EQ(view->frame(), 140 % 120);
  EXPECT_TRUE(
      view->caption().startsWith("Frame 20 (the play bar's frame 140: the 120-frame walk repeats)"))
      << view->caption().toStdString();
}

}  // namespace
}  // namespace oflab::test

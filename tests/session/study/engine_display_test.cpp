// The shown error from the real engine (session/study/engine_display.h): the perspective
// policy's measured error follows the threshold it is given and stays within it, the affine
// policy's is set by the motion, and a request is shown as the nearest measured error.
#include "study/engine_display.h"

#include <gtest/gtest.h>

namespace oflab {
namespace {

TEST(EngineDisplay, ThePerspectivePolicyShowsAnErrorWithinItsThreshold) {
  const StudyCondition c{"p", StudyPolicy::kPerspective, 30.0, StudyTexture::kButterfly, 60.0};
  const double small = clip_measured_error(c, 0.5), large = clip_measured_error(c, 4.0);
  EXPECT_LE(small, 0.5 * 1.001);
  EXPECT_GT(small, 0.25);
  EXPECT_LE(large, 4.0 * 1.001);
  EXPECT_GT(large, 2.0);
}

TEST(EngineDisplay, TheAffinePolicysErrorIsSetByTheMotion) {
  const StudyCondition c{"a", StudyPolicy::kAffine, 3.0, StudyTexture::kButterfly, 60.0};
  const double small = clip_measured_error(c, 0.2), large = clip_measured_error(c, 5.0);
  EXPECT_GT(small, 2.0);  // far above the threshold asked for
  EXPECT_NEAR(large / small, 1.0, 0.1);
}

TEST(EngineDisplay, ARequestIsShownAsTheNearestMeasuredErrorOnALogScale) {
  ErrorLadder ladder;
  ladder.thresholds_px = {0.5, 1.0, 2.0, 4.0};
  ladder.measured_px = {0.45, 0.9, 1.9, 3.2};
  EXPECT_DOUBLE_EQ(shown_error(ladder, 1.0), 0.9);
  EXPECT_DOUBLE_EQ(shown_error(ladder, 1.4), 1.9);  // log distance 0.31 against 0.44
  EXPECT_DOUBLE_EQ(shown_error(ladder, 100.0), 3.2);
  EXPECT_DOUBLE_EQ(shown_error(ladder, 0.01), 0.45);
}

}  // namespace
}  // namespace oflab

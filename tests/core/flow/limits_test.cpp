// The one rule per value (core/flow/limits.h): what a Limit allows, the words of its
// refusals, and the ranges the project's data and the dissertation's experiments rely on.
#include "flow/limits.h"

#include <gtest/gtest.h>

#include <limits>

#include "content/layer_content.h"

namespace oflab {
namespace {

constexpr Limit kPercent{"share", "%", 0.0, 100.0};
constexpr Limit kCount{"count", "", 1.0, 256.0, true};

TEST(Limit, AllowsTheClosedRangeAndNothingElse) {
  EXPECT_TRUE(kPercent.allows(0.0));
  EXPECT_TRUE(kPercent.allows(100.0));
  EXPECT_TRUE(kPercent.allows(37.5));
  EXPECT_FALSE(kPercent.allows(-1e-9));
  EXPECT_FALSE(kPercent.allows(100.000001));
  EXPECT_FALSE(kPercent.allows(std::numeric_limits<double>::quiet_NaN()));
  EXPECT_FALSE(kPercent.allows(std::numeric_limits<double>::infinity()));
  EXPECT_TRUE(kCount.allows(1.0));
  EXPECT_TRUE(kCount.allows(256.0));
  EXPECT_FALSE(kCount.allows(2.5));
  EXPECT_FALSE(kCount.allows(0.0));
}

TEST(Limit, ProblemNamesTheValueAndTheRange) {
  EXPECT_EQ(kPercent.problem(50.0), "");
  EXPECT_EQ(limits::kThreshold.problem(1e6), "1e+06 is outside 0..100 px");
  EXPECT_EQ(kPercent.problem(-3.0), "-3 is outside 0..100 %");
  EXPECT_EQ(kCount.problem(2.5), "2.5 is not a whole number (1..256)");
  EXPECT_EQ(kCount.problem(300.0), "300 is outside 1..256");
  EXPECT_EQ(kPercent.problem(std::numeric_limits<double>::infinity()),
            "inf is not a finite number");
}

TEST(Limit, RangeTextHasTheUnitWhenThereIsOne) {
  EXPECT_EQ(limits::kThreshold.range_text(), "0..100 px");
  EXPECT_EQ(limits::kContentQuality.range_text(), "1..256");
  EXPECT_EQ(limits::kVelocity.range_text(), "-1000..1000 u/s");
}

TEST(Limits, EveryRangeIsOrderedAndNamed) {
  for (const Limit& l :
       {limits::kThreshold, limits::kFocalLength, limits::kImageSize, limits::kDistance,
        limits::kTurn, limits::kTilt, limits::kPlaneSize, limits::kVelocity,
        limits::kAngularVelocity, limits::kFlowCoefficient, limits::kFrameCount,
        limits::kPlayedFrames, limits::kBudgetPixels, limits::kBudgetMs, limits::kContentQuality,
        limits::kZoom, limits::kPlayRate}) {
    EXPECT_LT(l.minimum, l.maximum) << l.what;
    EXPECT_STRNE(l.what, "");
  }
}

// The values the shipped data and the experiments use stay inside their limits
// (datasets/: focal 256 to 700 px, images 360 to 1280 px, |V| <= 0.1, |Omega| <= 0.05,
// segments of 14 to 629 frames, content quality 3; the threshold sweep 0.25 to 4 px).
TEST(Limits, AllowTheShippedDataAndTheExperiments) {
  EXPECT_TRUE(limits::kFocalLength.allows(256.0) && limits::kFocalLength.allows(700.0));
  EXPECT_TRUE(limits::kImageSize.allows(360.0) && limits::kImageSize.allows(1280.0));
  EXPECT_TRUE(limits::kVelocity.allows(-0.1) && limits::kAngularVelocity.allows(0.05));
  EXPECT_TRUE(limits::kPlayedFrames.allows(14.0) && limits::kPlayedFrames.allows(629.0));
  EXPECT_TRUE(limits::kThreshold.allows(0.25) && limits::kThreshold.allows(4.0));
  EXPECT_TRUE(limits::kContentQuality.allows(3.0));
  EXPECT_FALSE(limits::kPlayedFrames.allows(0.0));  // a run or a segment plays a frame
  EXPECT_EQ(limits::kPlayedFrames.maximum, limits::kFrameCount.maximum);
  EXPECT_EQ(kMaxContentQuality, limits::kContentQuality.maximum);  // one truth
}

}  // namespace
}  // namespace oflab

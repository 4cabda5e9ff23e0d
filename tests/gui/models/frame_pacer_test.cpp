// Live play follows the wall clock: the frames advanced after T seconds are floor(T * rate)
// however the ticks fall (counted here by hand for given tick times).
#include "models/frame_pacer.h"

#include <gtest/gtest.h>

#include <vector>

namespace oflab {
namespace {

int advanced_over(FramePacer* pacer, const std::vector<int>& ticks_ms) {
  int total = 0;
  for (int t : ticks_ms) total += pacer->frames_due(t);
  return total;
}

TEST(FramePacer, RegularTicksAdvanceOneFrameEach) {
  FramePacer pacer;
  pacer.start(1000, 30.0);
  std::vector<int> ticks;
  for (int k = 1; k <= 30; ++k) ticks.push_back(1000 + (k * 1000 + 29) / 30);
  for (int t : ticks) EXPECT_EQ(pacer.frames_due(t), 1) << "tick at " << t << " ms";
}

TEST(FramePacer, SlowDrawingDropsFramesAndKeepsRealSpeed) {
  // Drawing takes 70 ms: ticks come every 70 ms instead of every 33 ms.
  FramePacer pacer;
  pacer.start(0, 30.0);
  std::vector<int> ticks;
  for (int t = 70; t <= 2100; t += 70) ticks.push_back(t);
  EXPECT_EQ(advanced_over(&pacer, ticks), 63);  // floor(2.1 s * 30)
}

TEST(FramePacer, EarlyTicksAndABackwardsClockAdvanceNothing) {
  FramePacer pacer;
  pacer.start(500, 10.0);
  EXPECT_EQ(pacer.frames_due(550), 0);  // the first frame is due at 600 ms
  EXPECT_EQ(pacer.frames_due(600), 1);
  EXPECT_EQ(pacer.frames_due(400), 0);
  EXPECT_EQ(pacer.frames_due(1000), 4);
}

TEST(FramePacer, ANonPositiveRateIsTakenAsOneFramePerSecond) {
  FramePacer pacer;
  pacer.start(0, 0.0);
  EXPECT_DOUBLE_EQ(pacer.rate(), 1.0);
  EXPECT_EQ(pacer.frames_due(2500), 2);
}

}  // namespace
}  // namespace oflab

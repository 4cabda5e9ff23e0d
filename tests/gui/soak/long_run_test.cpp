// Long runs in the GUI (ctest label `soak`): the animation model, which the animation and
// analysis views read, plays 10 000 frames of the loop script, about sixteen times round its
// 629 frames as the window's clock does, and the process's peak resident memory after them
// stays within 10 % of its peak after the first 1000 (manual/robustness.md, "Long runs").
#include <gtest/gtest.h>

#include <fstream>
#include <iostream>
#include <string>

#include "models/animation_model.h"
#include "models/scene_model.h"

namespace oflab::test {
namespace {

// VmHWM of /proc/self/status: the peak resident memory of this process so far, KiB.
long peak_resident_kib() {
  std::ifstream status("/proc/self/status");
  for (std::string line; std::getline(status, line);) {
    if (line.rfind("VmHWM:", 0) == 0) return std::stol(line.substr(6));
  }
  return -1;
}

// Advances the scene model's clock `frames` times, the animation model following each.
void play(SceneModel& scene, AnimationModel& model, int frames) {
  for (int i = 0; i < frames; ++i) {
    scene.advance(1);
    ASSERT_NE(model.animator(), nullptr);
    ASSERT_EQ(model.animator()->frame(), scene.frame());
  }
}

TEST(LongRun, TenThousandFramesOfTheAnimationModelKeepThePeakMemoryFlat) {
  SceneModel scene;
  AnimationModel model(&scene);
  ASSERT_TRUE(model.set_source({"script", "loop", ""}));
  ASSERT_EQ(scene.loop_frames(), 629);
  play(scene, model, 1000);
  const long after_1000 = peak_resident_kib();
  ASSERT_GT(after_1000, 0);
  play(scene, model, 9000);
  const long after_10000 = peak_resident_kib();
  std::cout << "peak resident memory: after 1000 frames " << after_1000
            << " KiB, after 10000 frames " << after_10000 << " KiB\n";
  EXPECT_LE(after_10000, after_1000 * 1.10);
  // The model holds the records of the current pass round the script only.
  EXPECT_EQ(model.history().size(), static_cast<std::size_t>(10000 % 629 + 1));
}

}  // namespace
}  // namespace oflab::test

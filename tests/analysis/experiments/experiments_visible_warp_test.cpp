// Warping what shows (experiments_visible_warp.h) on short runs of small frames: the totals are
// the per-frame figures summed, the whole warp computes every pixel it writes, the
// visible-only warp fewer on the four cubes and the same bytes, and the section's text
// carries the figures the runs measured.
#include "experiments/experiments_visible_warp.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <variant>

#include "scratch_dir.h"

namespace oflab {
namespace {

namespace fs = std::filesystem;

// Four cubes (their first 24 frames: the slide, where cubes hide parts of each other) and the
// street straight on (its first 6 frames: a corridor, nothing hidden, every layer inside the
// frame), at a quarter of the scripts' size.
const VisibleWarpResult& short_runs() {
  static const VisibleWarpResult result = [] {
    VisibleWarpSpec spec;
    spec.sources = {{"four-cubes", "compound", 0, 24}, {"street", "walk", 0, 6}};
    spec.camera_divisor = 4;
    return run_visible_warp_experiment(spec, {});
  }();
  return result;
}

std::int64_t sum(const std::vector<std::int64_t>& v) {
  std::int64_t s = 0;
  for (std::int64_t x : v) s += x;
  return s;
}

TEST(VisibleWarpExperiment, TotalsAreThePerFrameFiguresSummed) {
  const VisibleWarpResult& r = short_runs();
  ASSERT_EQ(r.runs.size(), 2u);
  const VisibleWarpRun& cubes = r.runs[0];
  EXPECT_EQ(cubes.width, 160);
  EXPECT_EQ(cubes.height, 120);
  ASSERT_EQ(cubes.written.size(), 24u);
  ASSERT_EQ(cubes.whole.size(), 24u);
  ASSERT_EQ(cubes.visible.size(), 24u);
  EXPECT_EQ(cubes.total_whole(), sum(cubes.whole));
  EXPECT_EQ(cubes.total_visible(), sum(cubes.visible));
  EXPECT_DOUBLE_EQ(cubes.drop(), 1.0 - double(sum(cubes.visible)) / double(sum(cubes.whole)));
}

// The whole warp computes every pixel it writes; the visible-only warp fewer over the run where
// cubes hide each other (in a frame it may compute more: a reused layer computes then the
// pixels it left out before and shows now), and its frames are the whole warp's bytes. The street
// straight on hides nothing: the same pixels (the control: no drop where there is nothing to leave
// out).
TEST(VisibleWarpExperiment, TheVisibleWarpComputesFewerPixelsOfTheSameFrames) {
  const VisibleWarpResult& r = short_runs();
  for (const VisibleWarpRun& run : r.runs) {
    EXPECT_EQ(run.whole, run.written) << run.source.scene;
    EXPECT_EQ(run.differing_frames, 0) << run.source.scene;
  }
  EXPECT_LT(r.runs[0].total_visible(), r.runs[0].total_whole());
  EXPECT_GT(r.runs[0].drop(), 0.01);
  EXPECT_EQ(r.runs[1].total_visible(), r.runs[1].total_whole());
  EXPECT_EQ(r.runs[1].drop(), 0.0);
}

// The text and the chart's numbers are the runs': each source's line names its totals and its
// drop to a tenth of a percent, computed here from the per-frame figures.
TEST(VisibleWarpExperiment, TheSectionCarriesTheMeasuredTotalsAndDrop) {
  const VisibleWarpResult& r = short_runs();
  const fs::path dir = testing::fresh_test_dir("oflab-visible-warp-section");
  fs::create_directories(dir / "charts");
  fs::create_directories(dir / "data");
  ExperimentContext context(dir.string(), true, nullptr);
  const ReportSection section = visible_warp_section(r, context);
  std::string text;
  for (const ReportBlock& b : section.blocks) {
    if (const auto* p = std::get_if<ReportParagraph>(&b)) text += p->text + "\n";
  }
  for (const VisibleWarpRun& run : r.runs) {
    const double drop = 100.0 * (1.0 - double(sum(run.visible)) / double(sum(run.whole)));
    char percent[32];
    std::snprintf(percent, sizeof percent, "(%+.1f %%)", -drop == 0.0 ? 0.0 : -drop);
    const std::string line = std::to_string(sum(run.whole)) + " pixels warped whole, " +
                             std::to_string(sum(run.visible)) + " visible-only " + percent;
    EXPECT_NE(text.find(line), std::string::npos) << line << "\n" << text;
  }
  EXPECT_EQ(context.charts_written(), 1);
  EXPECT_TRUE(fs::is_regular_file(dir / "charts" / "visible-warp-pixels.png"));
  EXPECT_GT(fs::file_size(dir / "data" / "visible-warp-pixels.csv"), 100u);
  if (!::testing::Test::HasFailure()) fs::remove_all(dir);
}

}  // namespace
}  // namespace oflab

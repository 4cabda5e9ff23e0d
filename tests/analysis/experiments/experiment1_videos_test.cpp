// `oflab-cli experiments --videos`: Experiment 1's runs as video files, one per script and
// mode, each with the frames of the run (read back with giflib, video_decode.h).
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>

#include "cli_capture.h"
#include "experiments/experiments.h"
#include "experiments/experiments_single_plane.h"
#include "video_decode.h"

namespace oflab {
namespace {

namespace fs = std::filesystem;

TEST(Experiment1Videos, OneGifPerScriptAndModeWithTheRunsFrames) {
  const fs::path dir =
      fs::temp_directory_path() / ("oflab-experiment1-videos-test-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  ExperimentContext context(dir.string(), true, nullptr);
  context.set_video_format("gif");
  RunSpec spec;
  spec.max_frames = 4;
  const std::vector<std::string> videos = write_experiment1_videos(context, spec);
  ASSERT_EQ(videos.size(), experiment1_scripts().size() * experiment1_modes().size());
  EXPECT_EQ(videos.front(), "videos/exp1-" + experiment1_scripts().front() + "-" +
                                experiment1_modes().front()->name + ".gif");
  for (const std::string& v : videos) {
    const testing::SlurpedGif gif = testing::read_gif((dir / v).string());
    ASSERT_NE(gif, nullptr) << v;
    EXPECT_EQ(gif->ImageCount, 4) << v;
  }
  fs::remove_all(dir);
}

TEST(Experiment1Videos, BadFormatOrNoExperiment1IsAUsageError) {
  auto r = testing::run_cli_captured({"experiments", "--videos", "avi"});
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(r.err, "oflab-cli experiments: --videos: 'avi' is not one of mp4, gif, ogv\n");
  r = testing::run_cli_captured({"experiments", "--only", "warp", "--videos", "mp4"});
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("--only leaves out exp1"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace oflab

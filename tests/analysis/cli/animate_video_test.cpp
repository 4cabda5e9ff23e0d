// `oflab-cli animate --video`: every form writes its frames as a video of the format of the
// file's extension, read back with an independent decoder (video_decode.h), and the
// option keeps the CLI's contract (a one-line error naming it, exit code 2, no file
// overwritten without --force).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "cli_capture.h"
#include "scratch_dir.h"
#include "video_decode.h"

namespace oflab {
namespace {

namespace fs = std::filesystem;
using testing::run_cli_captured;

class AnimateVideo : public ::testing::Test {
 protected:
  void SetUp() override { dir_ = testing::fresh_test_dir("oflab-animate-video"); }
  void TearDown() override { fs::remove_all(dir_); }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  fs::path dir_;
};

TEST_F(AnimateVideo, PlaneRunAsMp4HasOneFramePerFrameAtTheCameraSize) {
  const auto r = run_cli_captured({"animate", "--script", "loop", "--frames", "12", "--video",
                                   path("loop.mp4"), "--fps", "24"});
  ASSERT_EQ(r.code, 0) << r.err;
  const testing::Decoded d = testing::decode_with_libav(path("loop.mp4"));
  EXPECT_EQ(d.frames, 12);
  EXPECT_EQ(d.width, 640);  // the scripts' camera: 640 x 480
  EXPECT_EQ(d.height, 480);
}

TEST_F(AnimateVideo, SceneRunAsGifHasTheRequestedFrames) {
  const auto r = run_cli_captured({"animate", "--scene", "two", "--script", "circle", "--frames",
                                   "6", "--video", path("two.gif")});
  ASSERT_EQ(r.code, 0) << r.err;
  const testing::SlurpedGif gif = testing::read_gif(path("two.gif"));
  ASSERT_NE(gif, nullptr);
  EXPECT_EQ(gif->ImageCount, 6);
}

TEST_F(AnimateVideo, ExistingFileNeedsForce) {
  std::ofstream(path("mine.mp4")) << "a user's file";
  const auto r = run_cli_captured(
      {"animate", "--script", "zoom", "--frames", "3", "--video", path("mine.mp4")});
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("--video: '" + path("mine.mp4") + "' exists (add --force"),
            std::string::npos)
      << r.err;
  EXPECT_EQ(fs::file_size(path("mine.mp4")), 13u);
  const auto forced = run_cli_captured(
      {"animate", "--script", "zoom", "--frames", "3", "--video", path("mine.mp4"), "--force"});
  ASSERT_EQ(forced.code, 0) << forced.err;
  EXPECT_EQ(testing::decode_with_libav(path("mine.mp4")).frames, 3);
}

TEST_F(AnimateVideo, BadValuesAreOneLineErrorsNamingTheOption) {
  const struct {
    std::vector<std::string> args;
    std::string message;
  } cases[] = {
      {{"--video", path("x.avi")},
       "--video: '" + path("x.avi") +
           "': the video format is chosen "
           "by the extension, one of mp4, gif, ogv"},
      {{"--video", path("x.gif"), "--fps", "0"}, "--fps: 0 is outside 1..60 fps"},
      {{"--fps", "25"}, "--fps: needs --video FILE"},
  };
  for (const auto& c : cases) {
    std::vector<std::string> args = {"animate", "--script", "zoom", "--frames", "2"};
    args.insert(args.end(), c.args.begin(), c.args.end());
    const auto r = run_cli_captured(args);
    EXPECT_EQ(r.code, 2) << c.message;
    EXPECT_EQ(r.err, "oflab-cli animate: " + c.message + "\n");
  }
  EXPECT_TRUE(fs::is_empty(dir_));
}

}  // namespace
}  // namespace oflab

// Video files: each format is read back with an independent decoder (libavformat and
// libavcodec for MP4 and Ogg Theora, giflib's reader for GIF) and its frame count, size
// and colours checked against the frames written.
#include "formats/video_file.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <vector>

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
}

#include "scratch_dir.h"
#include "video_decode.h"

namespace oflab {
namespace {

namespace fs = std::filesystem;
using testing::decode_with_libav;
using testing::Decoded;
using testing::read_gif;
using testing::SlurpedGif;

// A smooth pattern that moves with k: red ramps across, green down, blue with the frame.
Image test_frame(int width, int height, int k) {
  Image image(width, height);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      image.at(x, y) = Pixel{static_cast<std::uint8_t>((x * 4 + k * 8) % 256),
                             static_cast<std::uint8_t>(y * 255 / height),
                             static_cast<std::uint8_t>(k * 20 % 256), 255};
    }
  }
  return image;
}

// Mean absolute difference of the decoded first frame from `image` (RGB, over the decoded size).
double mean_rgb_difference(const Decoded& d, const Image& image) {
  double sum = 0.0;
  for (int y = 0; y < d.height; ++y) {
    for (int x = 0; x < d.width; ++x) {
      const std::uint8_t* got = &d.first_rgb[(static_cast<size_t>(y) * d.width + x) * 3];
      const Pixel& want = image.at(x, y);
      sum += std::abs(got[0] - want.r) + std::abs(got[1] - want.g) + std::abs(got[2] - want.b);
    }
  }
  return sum / (3.0 * d.width * d.height);
}

class VideoFileTest : public ::testing::Test {
 protected:
  void SetUp() override { dir_ = testing::fresh_test_dir("oflab-video-test"); }
  void TearDown() override { fs::remove_all(dir_); }

  std::string write(const std::string& name, int frames, int width, int height) {
    const std::string path = (dir_ / name).string();
    VideoWriter writer(path, 25, false);
    for (int k = 0; k < frames; ++k) writer.add_frame(test_frame(width, height, k));
    writer.finish();
    EXPECT_EQ(writer.frames(), frames);
    return path;
  }

  fs::path dir_;
};

TEST_F(VideoFileTest, Mp4DecodesWithFrameCountSizeAndColours) {
  // An odd size: H.264 4:2:0 stores the even part, 64 x 48.
  const std::string path = write("clip.mp4", 12, 65, 49);
  const Decoded d = decode_with_libav(path);
  EXPECT_EQ(d.frames, 12);
  EXPECT_EQ(d.width, 64);
  EXPECT_EQ(d.height, 48);
  ASSERT_FALSE(d.first_rgb.empty());
  // Lossy, with chroma at half resolution: a few levels of 255 on average at most.
  EXPECT_LT(mean_rgb_difference(d, test_frame(65, 49, 0)), 6.0);
}

TEST_F(VideoFileTest, Mp4UsesH264WhenLibavcodecHasIt) {
  const AVCodec* h264 = avcodec_find_encoder(AV_CODEC_ID_H264);
  if (!h264) GTEST_SKIP() << "this libavcodec has no H.264 encoder; MP4 falls back to mpeg4";
  const std::string name = mp4_encoder_name();
  EXPECT_TRUE(name == "libx264" || name == h264->name) << name;
  const std::string path = write("clip.mp4", 3, 32, 32);
  AVFormatContext* format = nullptr;
  ASSERT_EQ(avformat_open_input(&format, path.c_str(), nullptr, nullptr), 0);
  avformat_find_stream_info(format, nullptr);
  EXPECT_EQ(format->streams[0]->codecpar->codec_id, AV_CODEC_ID_H264);
  avformat_close_input(&format);
}

TEST_F(VideoFileTest, GifHasTheRequestedFramesAndExactSize) {
  const std::string path = write("clip.gif", 7, 33, 21);
  const SlurpedGif slurped = read_gif(path);
  const GifFileType* gif = slurped.get();
  ASSERT_NE(gif, nullptr);
  EXPECT_EQ(gif->ImageCount, 7);
  EXPECT_EQ(gif->SWidth, 33);
  EXPECT_EQ(gif->SHeight, 21);
  // Frame 0's pixel (10, 5) through its palette, against the frame written.
  const SavedImage& first = gif->SavedImages[0];
  const GifColorType c = first.ImageDesc.ColorMap->Colors[first.RasterBits[5 * 33 + 10]];
  const Pixel want = test_frame(33, 21, 0).at(10, 5);
  EXPECT_NEAR(c.Red, want.r, 12);
  EXPECT_NEAR(c.Green, want.g, 12);
  EXPECT_NEAR(c.Blue, want.b, 12);
  GraphicsControlBlock control;
  ASSERT_EQ(DGifSavedExtensionToGCB(slurped.get(), 0, &control), GIF_OK);
  EXPECT_EQ(control.DelayTime, 4);  // 25 fps: 4 hundredths of a second
}

TEST_F(VideoFileTest, OgvDecodesWithFrameCountAndSize) {
  const std::string path = write("clip.ogv", 5, 40, 30);
  const Decoded d = decode_with_libav(path);
  EXPECT_EQ(d.frames, 5);
  EXPECT_EQ(d.width, 40);
  EXPECT_EQ(d.height, 30);
}

TEST_F(VideoFileTest, FormatComesFromTheExtension) {
  EXPECT_EQ(video_format_of("a/b.MP4"), VideoFormat::kMp4);
  EXPECT_EQ(video_format_of("x.gif"), VideoFormat::kGif);
  EXPECT_EQ(video_format_of("x.ogv"), VideoFormat::kOgv);
  try {
    video_format_of("talk.avi");
    FAIL() << "an .avi was accepted";
  } catch (const VideoFileError& e) {
    EXPECT_NE(std::string(e.what()).find("talk.avi"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("mp4, gif, ogv"), std::string::npos);
  }
}

TEST_F(VideoFileTest, RefusesAnExistingFileUnlessTold) {
  const std::string path = (dir_ / "kept.gif").string();
  std::ofstream(path) << "user data";
  EXPECT_THROW(VideoWriter(path, 30, false), VideoFileError);
  EXPECT_EQ(fs::file_size(path), 9u);
  VideoWriter writer(path, 30, true);
  writer.add_frame(test_frame(8, 8, 0));
  writer.finish();
  EXPECT_GT(fs::file_size(path), 9u);
}

TEST_F(VideoFileTest, RejectsBadFrameRatesSizesAndEmptyVideos) {
  EXPECT_THROW(VideoWriter((dir_ / "a.mp4").string(), 0, false), VideoFileError);
  EXPECT_THROW(VideoWriter((dir_ / "a.mp4").string(), kMaxVideoFps + 1, false), VideoFileError);
  VideoWriter empty((dir_ / "empty.mp4").string(), 30, false);
  EXPECT_THROW(empty.finish(), VideoFileError);
  VideoWriter tiny((dir_ / "tiny.mp4").string(), 30, false);
  EXPECT_THROW(tiny.add_frame(test_frame(1, 9, 0)), VideoFileError);
}

TEST_F(VideoFileTest, SizeChangeFailsAndLeavesNoFile) {
  const std::string path = (dir_ / "broken.mp4").string();
  {
    VideoWriter writer(path, 30, false);
    writer.add_frame(test_frame(32, 24, 0));
    try {
      writer.add_frame(test_frame(30, 24, 1));
      FAIL() << "a frame of another size was accepted";
    } catch (const VideoFileError& e) {
      EXPECT_NE(std::string(e.what()).find("broken.mp4"), std::string::npos);
      EXPECT_NE(std::string(e.what()).find("30 x 24"), std::string::npos);
    }
  }
  EXPECT_FALSE(fs::exists(path));
}

}  // namespace
}  // namespace oflab

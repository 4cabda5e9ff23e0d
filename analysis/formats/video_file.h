// Video files from rendered frames, for slides and web pages: MP4 (H.264) and Ogg Theora
// through Debian's libavformat and libavcodec (encoders libx264 and libtheora), and
// animated GIF through giflib. The format is chosen by the file's extension. Frames are core Images
// (premultiplied RGBA8), shown over black: transparent pixels become black.
#pragma once

#include <memory>
#include <stdexcept>
#include <string>

#include "flow/limits.h"
#include "formats/atomic_file.h"
#include "image/image.h"

namespace oflab {

class VideoFileError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

enum class VideoFormat { kMp4, kGif, kOgv };

// The format of `path` by its extension: .mp4, .gif or .ogv, in any case. Throws
// VideoFileError naming the path and the accepted extensions for any other.
VideoFormat video_format_of(const std::string& path);

// "mp4", "gif", "ogv".
const char* video_format_name(VideoFormat format);

// "mp4, gif, ogv": the accepted extensions, for messages and help texts.
std::string video_format_list();

// Lowest and highest frame rate a VideoWriter accepts, in frames per second.
// (limits::kVideoFps).
constexpr int kMinVideoFps = static_cast<int>(limits::kVideoFps.minimum);
constexpr int kMaxVideoFps = static_cast<int>(limits::kVideoFps.maximum);

// The size in pixels a format stores for a width x height frame: MP4 and Ogg Theora need
// even sizes, so an odd last column or row is dropped; GIF keeps the frame's size.
struct VideoSize {
  int width = 0;
  int height = 0;
};
VideoSize stored_video_size(VideoFormat format, int width, int height);

// The encoder's name in libavcodec for MP4 files: "libx264" when Debian's libavcodec has it
// (bookworm's does), else the first H.264 encoder found, else "mpeg4" (MPEG-4 part 2, which
// every libavcodec has). Empty if none of these exists.
std::string mp4_encoder_name();

// Writes one video file, frame by frame, through a temporary file beside it
// (formats/atomic_file.h) that finish() renames over the path: a writer destroyed before
// finish() (a failed run) removes its temporary and leaves what was at the path. Not
// copyable. The temporary is created by the first frame, with the mode the umask gives.
class VideoWriter {
 public:
  // Prepares to write `path` (format by its extension) at `fps` frames per second. Throws
  // VideoFileError naming the path for an unknown extension, an fps outside
  // [kMinVideoFps, kMaxVideoFps], or an existing file when `overwrite` is false.
  // GIF stores frame delays in hundredths of a second: 30 fps plays at 100/3 fps.
  VideoWriter(const std::string& path, int fps, bool overwrite);
  ~VideoWriter();
  VideoWriter(const VideoWriter&) = delete;
  VideoWriter& operator=(const VideoWriter&) = delete;

  // Appends one frame. The first frame fixes the size (stored_video_size of it, at least
  // 2 x 2 pixels and at most limits::kVideoFramePixels, checked before the encoder is
  // opened); every later frame must have the first one's width and height. Throws
  // VideoFileError naming the path on a size mismatch, an empty, too small or too large
  // frame, or an encoder failure; FileWriteError naming the path when the file cannot be written.
  void add_frame(const Image& frame);

  // Flushes the encoder, closes the file and renames it over the path. Throws
  // VideoFileError naming the path when no frame was added or the encoder fails,
  // FileWriteError when the file cannot be completed (or, without `overwrite`, when a file
  // appeared at the path meanwhile). Calling it again does nothing.
  void finish();

  VideoFormat format() const { return format_; }
  int frames() const { return frames_; }
  const std::string& path() const { return path_; }

  // The encoder behind one format (defined in video_file.cpp).
  class Encoder;

 private:
  std::string path_;
  VideoFormat format_;
  int fps_;
  int frames_ = 0;
  int width_ = 0;  // of the first frame
  int height_ = 0;
  bool overwrite_ = false;
  bool finished_ = false;
  std::unique_ptr<AtomicFile> file_;  // the temporary file, from the first frame on
  std::unique_ptr<Encoder> encoder_;
};

}  // namespace oflab

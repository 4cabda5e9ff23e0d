// Reading videos back for the tests, with decoders independent of the writer's code:
// libavformat and libavcodec for MP4 and Ogg Theora, giflib's reader for GIF.
#pragma once

#include <gif_lib.h>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace oflab::testing {

struct Decoded {
  int frames = 0;  // 0 when the file cannot be opened as a video
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> first_rgb;  // the first frame, RGB24, rows top to bottom
};

// Decodes every frame of the best video stream of `path`.
Decoded decode_with_libav(const std::string& path);

// A GIF read whole by DGifSlurp (frames in SavedImages, ImageCount); null when `path`
// cannot be read as a GIF.
struct GifCloser {
  void operator()(GifFileType* gif) const;
};
using SlurpedGif = std::unique_ptr<GifFileType, GifCloser>;
SlurpedGif read_gif(const std::string& path);

}  // namespace oflab::testing

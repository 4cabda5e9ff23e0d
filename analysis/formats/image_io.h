// Reading and writing image files (PNG, JPEG, BMP, TGA in; PNG out), converting between
// the files' straight alpha and core's premultiplied RGBA8.
#pragma once

#include <stdexcept>
#include <string>

#include "image/image.h"

namespace oflab {

class ImageFileError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Reads an image file; images without alpha become opaque. Throws ImageFileError naming
// the path and the reason (missing, unreadable, not an image, too large).
Image read_image(const std::string& path);

// Writes `image` as an 8-bit RGBA PNG (straight alpha). Throws ImageFileError on failure.
// Overwrites `path`: callers decide whether that is allowed.
void write_png(const std::string& path, const Image& image);

}  // namespace oflab

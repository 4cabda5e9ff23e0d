// Reading and writing image files (PNG and JPEG in; PNG out), converting between the files'
// straight alpha and core's premultiplied RGBA8. A file is checked before it is decoded: its
// first bytes must be a PNG or JPEG signature and its header's size must be within the
// limits below, so a hostile file never reaches the decoder's allocations.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>

#include "formats/atomic_file.h"
#include "image/image.h"

namespace oflab {

class ImageFileError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Largest image file read, in bytes, and largest image, in pixels (width * height; each
// side is also at most kMaxImageDimension of core/image/image.h). 4096 x 4096 fits.
constexpr std::int64_t kMaxImageFileBytes = 256LL << 20;
constexpr std::int64_t kMaxImagePixels = 4096LL * 4096;

// An image's size in pixels, as its file's header declares it.
struct ImageFileSize {
  int width = 0;
  int height = 0;
};

// The width and height an image file's header declares. Throws ImageFileError naming the
// path and the reason: missing or unreadable, larger than kMaxImageFileBytes, not a PNG or
// JPEG (by its signature), a header stb_image cannot read, a zero size, a side above
// kMaxImageDimension or more than kMaxImagePixels pixels. Decodes no pixels.
ImageFileSize check_image_file(const std::string& path);

// Reads a PNG or JPEG file (checked first by check_image_file); images without alpha become
// opaque. Throws ImageFileError naming the path and the reason.
Image read_image(const std::string& path);

// Reads an image from bytes in memory, with the checks of read_image; `origin` names the
// source in errors.
Image decode_image(const std::string& bytes, const std::string& origin);

// `image` as the bytes of an 8-bit RGBA PNG (straight alpha). Throws ImageFileError for an
// empty image.
std::string encode_png(const Image& image);

// Writes `image` as an 8-bit RGBA PNG (straight alpha) through a temporary file renamed over
// `path` (formats/atomic_file.h): a failed write leaves what was at `path`. With
// Overwrite::kRefuse an existing `path` is refused. Throws ImageFileError for an empty image,
// FileWriteError naming the path when the file cannot be written.
void write_png(const std::string& path, const Image& image,
               Overwrite overwrite = Overwrite::kReplace);

}  // namespace oflab

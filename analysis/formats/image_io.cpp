#include "formats/image_io.h"

#include <stb/stb_image.h>
#include <stb/stb_image_write.h>

#include <algorithm>
#include <cstring>
#include <memory>
#include <utility>

#include "formats/input_file.h"

namespace oflab {
namespace {

// The contents of `path`, refused above kMaxImageFileBytes (formats/input_file.h: a regular
// file only, its size checked while it is read).
std::string read_bytes(const std::string& path) {
  InputFile file = read_input_file(path, kMaxImageFileBytes);
  if (file.problem == InputProblem::kTooLarge) {
    throw ImageFileError(path + ": image file is larger than " +
                         std::to_string(kMaxImageFileBytes >> 20) + " MiB");
  }
  if (file.problem != InputProblem::kNone) {
    throw ImageFileError(path + ": cannot read image (" + input_problem_text(file) + ")");
  }
  return std::move(file.bytes);
}

// Appends what stbi_write_png_to_func hands on to a std::string.
void append_bytes(void* context, void* data, int size) {
  static_cast<std::string*>(context)->append(static_cast<const char*>(data),
                                             static_cast<std::size_t>(size));
}

// Why stb_image failed last: its own words, or (it gives none when an allocation failed
// before it could say) "out of memory".
std::string stb_failure() {
  const char* reason = stbi_failure_reason();
  return reason && *reason ? reason : "out of memory";
}

bool starts_with(const std::string& bytes, const char* signature, size_t length) {
  return bytes.size() >= length && std::memcmp(bytes.data(), signature, length) == 0;
}

// Big-endian 32-bit value at byte `at` of `bytes`. Precondition: at + 4 <= bytes.size().
std::uint32_t be32(const std::string& bytes, size_t at) {
  std::uint32_t v = 0;
  for (size_t k = 0; k < 4; ++k) v = (v << 8) | static_cast<unsigned char>(bytes[at + k]);
  return v;
}

// The size in a PNG's IHDR chunk (always first, at byte 8), when the bytes have one.
bool png_header_size(const std::string& bytes, ImageFileSize* size) {
  if (bytes.size() < 24 || bytes.compare(12, 4, "IHDR") != 0) return false;
  // Sides beyond 2^31 are reported as the largest int: refused by the limits all the same.
  size->width = static_cast<int>(std::min<std::uint32_t>(be32(bytes, 16), 0x7fffffff));
  size->height = static_cast<int>(std::min<std::uint32_t>(be32(bytes, 20), 0x7fffffff));
  return true;
}

// Walks a PNG's chunks (length, type, data, CRC) after the signature up to IEND and refuses
// one whose length reaches past the end of the bytes: stb_image allocates a chunk's declared
// length before it reads the data, so a few damaged bytes could ask for gigabytes.
void check_png_chunks(const std::string& bytes, const std::string& origin) {
  size_t at = 8;
  while (at + 8 <= bytes.size()) {
    const std::uint64_t length = be32(bytes, at);
    const std::string type = bytes.substr(at + 4, 4);
    const std::uint64_t left = bytes.size() - at - 8;
    if (length + 4 > left) {
      throw ImageFileError(origin + ": PNG chunk '" + type + "' at byte " + std::to_string(at) +
                           " declares " + std::to_string(length) + " bytes of data, but " +
                           std::to_string(left) +
                           " bytes (its CRC included) are left in the file: truncated or damaged");
    }
    if (type == "IEND") return;
    at += 12 + length;
  }
}

// The checks of check_image_file on bytes in memory.
ImageFileSize check_image_bytes(const std::string& bytes, const std::string& origin) {
  const bool png = starts_with(bytes, "\x89PNG\r\n\x1a\n", 8);
  if (!png && !starts_with(bytes, "\xff\xd8\xff", 3)) {
    throw ImageFileError(origin + ": not a PNG or JPEG file (the only image formats read)");
  }
  const auto* data = reinterpret_cast<const stbi_uc*>(bytes.data());
  const int length = static_cast<int>(bytes.size());
  ImageFileSize size;
  int channels = 0;
  if (png && png_header_size(bytes, &size)) {
    // stb_image refuses some large PNGs itself, but names no size: check ours first.
  } else if (!stbi_info_from_memory(data, length, &size.width, &size.height, &channels)) {
    throw ImageFileError(origin + ": cannot read image header (" + stb_failure() + ")");
  }
  if (size.width < 1 || size.height < 1) throw ImageFileError(origin + ": image is empty");
  if (size.width > kMaxImageDimension || size.height > kMaxImageDimension ||
      std::int64_t(size.width) * size.height > kMaxImagePixels) {
    throw ImageFileError(origin + ": image of " + std::to_string(size.width) + " x " +
                         std::to_string(size.height) + " pixels is larger than the limit (" +
                         std::to_string(kMaxImagePixels) + " pixels, " +
                         std::to_string(kMaxImageDimension) + " on a side)");
  }
  if (png) check_png_chunks(bytes, origin);
  return size;
}

}  // namespace

ImageFileSize check_image_file(const std::string& path) {
  return check_image_bytes(read_bytes(path), path);
}

Image decode_image(const std::string& bytes, const std::string& origin) {
  const ImageFileSize size = check_image_bytes(bytes, origin);
  int w = 0, h = 0, channels = 0;
  std::unique_ptr<unsigned char, void (*)(void*)> data(
      stbi_load_from_memory(reinterpret_cast<const stbi_uc*>(bytes.data()),
                            static_cast<int>(bytes.size()), &w, &h, &channels, 4),
      stbi_image_free);
  if (!data) throw ImageFileError(origin + ": cannot read image (" + stb_failure() + ")");
  if (w != size.width || h != size.height) {
    throw ImageFileError(origin + ": cannot read image (the header's size is not the image's)");
  }
  const std::vector<std::uint8_t> pixels(data.get(), data.get() + static_cast<size_t>(w) * h * 4);
  return image_from_straight_rgba(w, h, pixels);
}

Image read_image(const std::string& path) { return decode_image(read_bytes(path), path); }

std::string encode_png(const Image& image) {
  if (image.empty()) throw ImageFileError("refusing to encode an empty image");
  const std::vector<std::uint8_t> pixels = straight_rgba_from_image(image);
  std::string png;
  if (!stbi_write_png_to_func(append_bytes, &png, image.width(), image.height(), 4, pixels.data(),
                              image.width() * 4)) {
    throw ImageFileError("cannot encode a PNG of " + std::to_string(image.width()) + " x " +
                         std::to_string(image.height()) + " pixels");
  }
  return png;
}

void write_png(const std::string& path, const Image& image, Overwrite overwrite) {
  if (image.empty()) throw ImageFileError(path + ": refusing to write an empty image");
  write_file_atomically(path, encode_png(image), overwrite);
}

}  // namespace oflab

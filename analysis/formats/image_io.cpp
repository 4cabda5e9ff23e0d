#include "formats/image_io.h"

#include <memory>

#include <stb/stb_image.h>
#include <stb/stb_image_write.h>

namespace oflab {

Image read_image(const std::string& path) {
  int w = 0, h = 0, channels = 0;
  std::unique_ptr<unsigned char, void (*)(void*)> data(
      stbi_load(path.c_str(), &w, &h, &channels, 4), stbi_image_free);
  if (!data) {
    throw ImageFileError(path + ": cannot read image (" + stbi_failure_reason() + ")");
  }
  if (w > kMaxImageDimension || h > kMaxImageDimension) {
    throw ImageFileError(path + ": image is larger than " + std::to_string(kMaxImageDimension) +
                         " pixels on a side");
  }
  const std::vector<std::uint8_t> bytes(data.get(), data.get() + static_cast<size_t>(w) * h * 4);
  return image_from_straight_rgba(w, h, bytes);
}

void write_png(const std::string& path, const Image& image) {
  if (image.empty()) throw ImageFileError(path + ": refusing to write an empty image");
  const std::vector<std::uint8_t> bytes = straight_rgba_from_image(image);
  if (!stbi_write_png(path.c_str(), image.width(), image.height(), 4, bytes.data(),
                      image.width() * 4)) {
    throw ImageFileError(path + ": cannot write PNG");
  }
}

}  // namespace oflab

// RGBA8 premultiplied images: storage and alpha conversions.
#include "image/image.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "image/pixel_math.h"
#include "image/thread_pool.h"

namespace oflab {
namespace {

void check_dimensions(int width, int height) {
  if (width < 0 || height < 0 || width > kMaxImageDimension || height > kMaxImageDimension) {
    throw std::invalid_argument("Image: size " + std::to_string(width) + " x " +
                                std::to_string(height) + " is outside 0.." +
                                std::to_string(kMaxImageDimension));
  }
}

std::uint8_t unpremultiply_channel(std::uint8_t c, std::uint8_t a) {
  const unsigned value = (static_cast<unsigned>(c) * 255u + a / 2u) / a;
  return static_cast<std::uint8_t>(std::min(value, 255u));
}

}  // namespace

Pixel premultiply(Pixel straight) {
  const unsigned a = straight.a;
  return Pixel{div255_round(straight.r * a), div255_round(straight.g * a),
               div255_round(straight.b * a), straight.a};
}

Pixel unpremultiply(Pixel premultiplied) {
  if (premultiplied.a == 0) return Pixel{};
  const std::uint8_t a = premultiplied.a;
  return Pixel{unpremultiply_channel(premultiplied.r, a), unpremultiply_channel(premultiplied.g, a),
               unpremultiply_channel(premultiplied.b, a), a};
}

Image::Image(int width, int height, Pixel fill) {
  check_dimensions(width, height);
  if (width == 0 || height == 0) return;
  width_ = width;
  height_ = height;
  pixels_.assign(static_cast<std::size_t>(width) * static_cast<std::size_t>(height), fill);
}

void Image::fill(Pixel value) {
  // In bands of rows on the worker threads (core/image/thread_pool.h): a camera-sized frame
  // is megabytes of stores.
  Pixel* pixels = pixels_.data();
  const std::size_t width = static_cast<std::size_t>(width_);
  for_each_band(height_, std::max(8, 65536 / std::max(width_, 1)), [&](int, int begin, int end) {
    std::fill(pixels + width * static_cast<std::size_t>(begin),
              pixels + width * static_cast<std::size_t>(end), value);
  });
}

Image& Image::operator=(const Image& other) {
  if (this == &other) return *this;
  grow_storage(other.pixels_.size());
  pixels_.assign(other.pixels_.begin(), other.pixels_.end());  // strong: no change if it throws
  width_ = other.width_;
  height_ = other.height_;
  return *this;
}

void Image::reshape(int width, int height) {
  check_dimensions(width, height);
  const bool empty = width == 0 || height == 0;
  width_ = empty ? 0 : width;
  height_ = empty ? 0 : height;
  // resize() never gives memory back, so a buffer that shrinks and grows again stays put.
  const std::size_t n = static_cast<std::size_t>(width_) * static_cast<std::size_t>(height_);
  grow_storage(n);
  pixels_.resize(n);
}

void Image::grow_storage(std::size_t n) {
  if (pixels_.capacity() > 0 && pixels_.capacity() < n) pixels_.reserve(n + n / 4);
}

Image image_from_straight_rgba(int width, int height,
                               const std::vector<std::uint8_t>& straight_rgba) {
  check_dimensions(width, height);
  const std::size_t needed = static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4;
  if (straight_rgba.size() < needed) {
    throw std::invalid_argument("image_from_straight_rgba: buffer holds " +
                                std::to_string(straight_rgba.size()) + " bytes, " +
                                std::to_string(needed) + " needed");
  }
  Image image(width, height);
  for (std::size_t i = 0; i < image.pixel_count(); ++i) {
    const std::uint8_t* p = &straight_rgba[i * 4];
    image.pixels()[i] = premultiply(Pixel{p[0], p[1], p[2], p[3]});
  }
  return image;
}

std::vector<std::uint8_t> straight_rgba_from_image(const Image& image) {
  std::vector<std::uint8_t> bytes(image.pixel_count() * 4);
  for (std::size_t i = 0; i < image.pixel_count(); ++i) {
    const Pixel p = unpremultiply(image.pixels()[i]);
    bytes[i * 4 + 0] = p.r;
    bytes[i * 4 + 1] = p.g;
    bytes[i * 4 + 2] = p.b;
    bytes[i * 4 + 3] = p.a;
  }
  return bytes;
}

void premultiply_in_place(Image& image) {
  for (Pixel& p : image.pixels()) p = premultiply(p);
}

}  // namespace oflab

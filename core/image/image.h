// RGBA8 images with premultiplied alpha: the pixel storage of layer images (dissertation
// appendix A.1) and of rendered frames.
//
// Coordinates: column x grows to the right, row y grows downwards, both 0-based. Pixel
// (x, y) covers the square [x, x+1) x [y, y+1) of continuous pixel coordinates and its
// centre is at (x + 0.5, y + 0.5). Every warp, scan conversion and compositing routine in
// core/ uses this convention (see manual/warping.md).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace oflab {

// Largest width or height accepted for an image, in pixels. The warp kernels rely on it
// for their exact fixed-point arithmetic (see core/image/inverse_map.h).
constexpr int kMaxImageDimension = 16384;

// One RGBA8 pixel. In an Image the colour channels are premultiplied by alpha:
// r, g, b <= a always holds for a well-formed premultiplied pixel.
struct alignas(4) Pixel {
  std::uint8_t r = 0;
  std::uint8_t g = 0;
  std::uint8_t b = 0;
  std::uint8_t a = 0;
};

inline bool operator==(const Pixel& p, const Pixel& q) {
  return p.r == q.r && p.g == q.g && p.b == q.b && p.a == q.a;
}
inline bool operator!=(const Pixel& p, const Pixel& q) { return !(p == q); }

// Premultiplies one straight-alpha pixel: each colour channel becomes
// round(c * a / 255). Exact integer rounding (halves round up).
Pixel premultiply(Pixel straight);

// Inverse of premultiply, up to rounding: c = round(c' * 255 / a), and (0, 0, 0, 0) when
// a == 0 (the colour of a fully transparent pixel is lost). Channels are clamped to 255
// if the input is not well-formed (c' > a).
Pixel unpremultiply(Pixel premultiplied);

// A width x height raster of premultiplied RGBA8 pixels, stored row-major without
// padding: pixel (x, y) is pixels()[y * width() + x]. A default-constructed image is
// empty (0 x 0). Copyable and movable; copies are deep.
class Image {
 public:
  Image() = default;

  // Creates a width x height image filled with `fill` (default: transparent black).
  // Throws std::invalid_argument if width or height is negative or exceeds
  // kMaxImageDimension. A zero width or height gives an empty image.
  Image(int width, int height, Pixel fill = Pixel{});

  Image(const Image&) = default;
  Image(Image&&) noexcept = default;
  Image& operator=(Image&&) noexcept = default;
  // Copies `other`'s size and pixels. Storage already in use that is too small grows with a
  // quarter of headroom (grow_storage). An empty destination takes exactly what it needs.
  Image& operator=(const Image& other);

  int width() const { return width_; }
  int height() const { return height_; }
  bool empty() const { return width_ == 0 || height_ == 0; }
  std::size_t pixel_count() const { return pixels_.size(); }

  // Row y as a pointer to width() pixels. Precondition: 0 <= y < height().
  Pixel* row(int y) { return pixels_.data() + static_cast<std::size_t>(y) * width_; }
  const Pixel* row(int y) const { return pixels_.data() + static_cast<std::size_t>(y) * width_; }

  // Pixel (x, y). Precondition: 0 <= x < width(), 0 <= y < height() (not checked).
  Pixel& at(int x, int y) { return row(y)[x]; }
  const Pixel& at(int x, int y) const { return row(y)[x]; }

  std::vector<Pixel>& pixels() { return pixels_; }
  const std::vector<Pixel>& pixels() const { return pixels_; }

  // Sets every pixel to `value`.
  void fill(Pixel value);

  // Makes the image width x height, keeping its storage when that is large enough (no
  // allocation then), else growing storage in use as grow_storage does: pixel values are
  // unspecified afterwards, the caller writes them all. Throws std::invalid_argument as the
  // constructor does.
  void reshape(int width, int height);

 private:
  // Storage in use that is too small for n pixels grows with a quarter of headroom: a layer
  // written into kept memory frame after frame as it grows (a facade coming nearer) is then
  // not reallocated, and its pages faulted in anew, on every frame (std::vector grows by
  // its size, not its capacity: after a shrink it would grow to exactly n).
  void grow_storage(std::size_t n);

  int width_ = 0;
  int height_ = 0;
  std::vector<Pixel> pixels_;
};

// Builds a premultiplied image from straight-alpha RGBA8 bytes (4 bytes per pixel, row
// after row, no padding, as written by most image files). Precondition: `straight_rgba`
// holds at least width * height * 4 bytes. Throws std::invalid_argument on a negative or
// too large size, or if the buffer is shorter than that.
Image image_from_straight_rgba(int width, int height,
                               const std::vector<std::uint8_t>& straight_rgba);

// The inverse: straight-alpha RGBA8 bytes of a premultiplied image (see unpremultiply).
std::vector<std::uint8_t> straight_rgba_from_image(const Image& image);

// Premultiplies every pixel of an image holding straight-alpha pixels, in place.
void premultiply_in_place(Image& image);

}  // namespace oflab

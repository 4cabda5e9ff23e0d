// Benchmark case definitions (see warp_cases.h).
#include "warp_cases.h"

#include <cmath>
#include <cstdlib>
#include <random>

#include "image/image.h"

namespace oflab::bench {
namespace {

constexpr double kPi = 3.14159265358979323846;

// A smooth pattern with some noise: content does not change the timings, but a constant
// image could hide bugs in the copies.
Image test_image(int width, int height) {
  Image image(width, height);
  std::mt19937 rng(42);
  std::uniform_int_distribution<int> noise(0, 31);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const auto r = static_cast<std::uint8_t>((x * 255) / std::max(width - 1, 1));
      const auto g = static_cast<std::uint8_t>((y * 255) / std::max(height - 1, 1));
      const auto b = static_cast<std::uint8_t>(((x ^ y) & 0xe0) | noise(rng));
      image.at(x, y) = Pixel{r, g, b, 255};
    }
  }
  return image;
}

Mat3 rotation_about(double degrees, double cx, double cy) {
  const double t = degrees * kPi / 180.0;
  return translation_matrix(cx, cy) *
         mat3_from_rows({std::cos(t), -std::sin(t), 0.0}, {std::sin(t), std::cos(t), 0.0},
                        {0.0, 0.0, 1.0}) *
         translation_matrix(-cx, -cy);
}

// Pixel -> normalised image units: centre at the origin, one unit = the image width.
Mat3 to_normalised(int width, int height) {
  return mat3_from_rows({1.0 / width, 0.0, -0.5}, {0.0, 1.0 / width, -0.5 * height / width},
                        {0.0, 0.0, 1.0});
}

std::int64_t count_polygon_pixels(const WarpCase& c) {
  Image probe(c.output_width, c.output_height);
  WarpOptions options;
  options.kernel = WarpKernel::kPerspective;
  return warp_layer_into(c.source, c.warp, probe, c.origin_x, c.origin_y, options).pixels_written;
}

// A case whose output pixel (0, 0) has its corner at destination (origin_x, origin_y).
WarpCase make_case(const std::string& size, const std::string& name, const Layer& source,
                   const Mat3& warp, int output_width, int output_height, int origin_x,
                   int origin_y) {
  WarpCase c;
  c.size = size;
  c.matrix = name;
  c.source = source;
  c.warp = warp;
  c.affine = is_affine(warp);
  c.output_width = output_width;
  c.output_height = output_height;
  c.origin_x = origin_x;
  c.origin_y = origin_y;
  c.polygon_pixels = count_polygon_pixels(c);
  return c;
}

// Output sized to the warped polygon's bounding box.
WarpCase boxed_case(const std::string& size, const std::string& name, const Layer& source,
                    const Mat3& warp) {
  const WarpedLayer probe = warp_layer(source, warp);
  return make_case(size, name, source, warp, probe.layer.image.width(), probe.layer.image.height(),
                   probe.offset_x, probe.offset_y);
}

}  // namespace

void set_peer_counters(benchmark::State& state, const WarpCase& c, const Image& peer_output,
                       Sampling sampling) {
  state.counters["agree"] = agreement(c, peer_output, sampling);
  state.counters["Mpx/s"] = benchmark::Counter(static_cast<double>(c.polygon_pixels) * 1e-6,
                                               benchmark::Counter::kIsIterationInvariantRate);
}

double agreement(const WarpCase& c, const Image& peer_output, Sampling sampling) {
  WarpOptions options;
  options.sampling = sampling;
  const Pixel unwritten{1, 2, 3, 0};  // not premultiplied: no warp writes it
  Image reference(c.output_width, c.output_height, unwritten);
  warp_layer_into(c.source, c.warp, reference, c.origin_x, c.origin_y, options);
  std::int64_t inside = 0;
  std::int64_t agree = 0;
  const int tolerance = sampling == Sampling::kBilinear ? 2 : 0;
  for (int y = 0; y < c.output_height; ++y) {
    for (int x = 0; x < c.output_width; ++x) {
      const Pixel a = reference.at(x, y);
      if (a == unwritten) continue;  // outside the polygon
      const Pixel b = peer_output.at(x, y);
      ++inside;
      agree += std::abs(a.r - b.r) <= tolerance && std::abs(a.g - b.g) <= tolerance &&
               std::abs(a.b - b.b) <= tolerance && std::abs(a.a - b.a) <= tolerance;
    }
  }
  return inside > 0 ? static_cast<double>(agree) / static_cast<double>(inside) : 1.0;
}

std::vector<WarpCase> appendix_a2_cases() {
  const Mat3 m = mat3_from_rows({0.8, 0.6, 0.0}, {-0.4, 0.8, 0.0}, {0.1, -0.3, 1.0});
  Mat3 m_affine = m;
  entry(m_affine, 2, 0) = 0.0;
  entry(m_affine, 2, 1) = 0.0;
  std::vector<WarpCase> cases;
  for (const auto& [w, h] : {std::pair{243, 198}, std::pair{121, 99}}) {
    const std::string size = std::to_string(w) + "x" + std::to_string(h);
    const Layer source = make_layer(test_image(w, h));
    const Mat3 n = to_normalised(w, h);
    const Mat3 n_inverse = glm::inverse(n);
    cases.push_back(boxed_case(size, "identity", source, Mat3(1.0)));
    cases.push_back(boxed_case(size, "rot45", source, rotation_about(45.0, 0.5 * w, 0.5 * h)));
    cases.push_back(boxed_case(size, "M-affine", source, n_inverse * m_affine * n));
    cases.push_back(boxed_case(size, "M", source, n_inverse * m * n));
  }
  return cases;
}

std::vector<WarpCase> frame_cases() {
  std::vector<WarpCase> cases;
  for (const auto& [w, h] : {std::pair{1024, 768}, std::pair{1920, 1080}}) {
    const std::string size = std::to_string(w) + "x" + std::to_string(h);
    const Layer source = make_layer(test_image(w, h));
    const double cx = 0.5 * w;
    const double cy = 0.5 * h;
    const double f = w;
    const double t = 20.0 * kPi / 180.0;
    const Mat3 k = mat3_from_rows({f, 0.0, cx}, {0.0, f, cy}, {0.0, 0.0, 1.0});
    const Mat3 pitch = mat3_from_rows({1.0, 0.0, 0.0}, {0.0, std::cos(t), -std::sin(t)},
                                      {0.0, std::sin(t), std::cos(t)});
    const Mat3 zoom = translation_matrix(cx, cy) *
                      mat3_from_rows({0.85, 0.0, 0.0}, {0.0, 0.85, 0.0}, {0.0, 0.0, 1.0}) *
                      translation_matrix(-cx, -cy);
    for (const auto& [name, warp] :
         {std::pair{std::string("rotation"), rotation_about(45.0, cx, cy)},
          std::pair{std::string("tilt"), zoom * k * pitch * glm::inverse(k)}}) {
      cases.push_back(make_case(size, name, source, warp, w, h, 0, 0));
    }
  }
  return cases;
}

}  // namespace oflab::bench

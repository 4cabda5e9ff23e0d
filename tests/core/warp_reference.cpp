// Per-pixel reference warp and random inputs for the warp tests (see warp_reference.h).
#include "warp_reference.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <sstream>
#include <string>

namespace oflab::testing {
namespace {

__extension__ typedef __int128 Int128;  // GCC and Clang; exact products of int64

Int128 linear(std::int64_t p, std::int64_t q, std::int64_t r, std::int64_t X, std::int64_t Y) {
  return Int128{p} * X + Int128{q} * Y + Int128{r};
}

std::int64_t floor_div128(Int128 n, Int128 d) {
  Int128 q = n / d;
  if (n % d != 0 && n < 0) --q;
  return static_cast<std::int64_t>(q);
}

double channel(const Pixel& p, int c) {
  const std::uint8_t values[4] = {p.r, p.g, p.b, p.a};
  return values[c];
}

std::vector<Vec2> convex_hull(std::vector<Vec2> points) {
  std::sort(points.begin(), points.end(),
            [](const Vec2& a, const Vec2& b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
  auto turn = [](const Vec2& o, const Vec2& a, const Vec2& b) {
    return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
  };
  std::vector<Vec2> hull(2 * points.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    while (k >= 2 && turn(hull[k - 2], hull[k - 1], points[i]) <= 0) --k;
    hull[k++] = points[i];
  }
  for (std::size_t i = points.size() - 1, t = k + 1; i-- > 0;) {
    while (k >= t && turn(hull[k - 2], hull[k - 1], points[i]) <= 0) --k;
    hull[k++] = points[i];
  }
  hull.resize(k > 1 ? k - 1 : k);
  return hull;
}

// The mip levels in double, each the unrounded 2 x 2 mean of the one below (taps beyond an
// odd edge clamped), level 0 the source: the reference's own pyramid.
struct DoubleLevel {
  int width = 0, height = 0;
  std::vector<double> values;  // 4 per pixel
  double at(std::int64_t x, std::int64_t y, int c) const {
    x = std::clamp<std::int64_t>(x, 0, width - 1);
    y = std::clamp<std::int64_t>(y, 0, height - 1);
    return values[static_cast<std::size_t>((y * width + x) * 4 + c)];
  }
};

std::vector<DoubleLevel> double_pyramid(const Image& source) {
  std::vector<DoubleLevel> levels(1);
  levels[0].width = source.width();
  levels[0].height = source.height();
  for (int y = 0; y < source.height(); ++y) {
    for (int x = 0; x < source.width(); ++x) {
      for (int c = 0; c < 4; ++c) levels[0].values.push_back(channel(source.at(x, y), c));
    }
  }
  while (levels.back().width > 1 || levels.back().height > 1) {
    const DoubleLevel& fine = levels.back();
    DoubleLevel coarse;
    coarse.width = (fine.width + 1) / 2;
    coarse.height = (fine.height + 1) / 2;
    for (int y = 0; y < coarse.height; ++y) {
      for (int x = 0; x < coarse.width; ++x) {
        for (int c = 0; c < 4; ++c) {
          const auto x1 = std::min(2 * x + 1, fine.width - 1);
          const auto y1 = std::min(2 * y + 1, fine.height - 1);
          coarse.values.push_back(0.25 * (fine.at(2 * x, 2 * y, c) + fine.at(x1, 2 * y, c) +
                                          fine.at(2 * x, y1, c) + fine.at(x1, y1, c)));
        }
      }
    }
    levels.push_back(std::move(coarse));
  }
  return levels;
}

// Bilinear in double of a level at (u, v), pixel-centre index coordinates, taps clamped.
double bilinear_double(const DoubleLevel& level, double u, double v, int c) {
  const double fu = std::floor(u), fv = std::floor(v);
  const double fx = u - fu, fy = v - fv;
  const auto x = static_cast<std::int64_t>(fu), y = static_cast<std::int64_t>(fv);
  return (1 - fx) * (1 - fy) * level.at(x, y, c) + fx * (1 - fy) * level.at(x + 1, y, c) +
         (1 - fx) * fy * level.at(x, y + 1, c) + fx * fy * level.at(x + 1, y + 1, c);
}

// The source point (continuous coordinates) of the integer map at doubled output
// coordinates (X, Y), for a map with the bilinear half-pixel shift; (X, Y) need not be
// integers here.
Vec2 source_point(const InverseMap& m, double X, double Y) {
  auto lin = [&](std::int64_t p, std::int64_t q, std::int64_t r) {
    return static_cast<double>(p) * X + static_cast<double>(q) * Y + static_cast<double>(r);
  };
  const double d = lin(m.g, m.h, m.i);
  return Vec2(lin(m.a, m.b, m.c) / d + 0.5, lin(m.d, m.e, m.f) / d + 0.5);
}

// Trilinear mipmap sample at output pixel (x, y): the footprint's longer axis by central
// differences of the map (steps of 1/1000 pixel) and a brute-force maximum over directions, the
// level its log2 clamped to [0, top], bilinear on the two levels around it blended.
void mipmap_reference(const InverseMap& m, const std::vector<DoubleLevel>& levels, int x, int y,
                      double* value) {
  const double X = 2.0 * x + 1.0, Y = 2.0 * y + 1.0, h = 1e-3;  // h: a pixel is 2 in X
  const Vec2 s = source_point(m, X, Y);
  const Vec2 dx = (source_point(m, X + h, Y) - source_point(m, X - h, Y)) / h;
  const Vec2 dy = (source_point(m, X, Y + h) - source_point(m, X, Y - h)) / h;
  double sigma = 0.0;
  for (int k = 0; k < 180; ++k) {
    const double t = k * 3.14159265358979323846 / 180.0;
    sigma = std::max(sigma, glm::length(std::cos(t) * dx + std::sin(t) * dy));
  }
  const int top = static_cast<int>(levels.size()) - 1;
  const double level = std::clamp(sigma > 1.0 ? std::log2(sigma) : 0.0, 0.0, double(top));
  const int lower = std::min(static_cast<int>(level), top);
  const int upper = std::min(lower + 1, top);
  const double t = level - lower;
  for (int c = 0; c < 4; ++c) {
    const double a =
        bilinear_double(levels[static_cast<std::size_t>(lower)], std::ldexp(s.x, -lower) - 0.5,
                        std::ldexp(s.y, -lower) - 0.5, c);
    const double b =
        bilinear_double(levels[static_cast<std::size_t>(upper)], std::ldexp(s.x, -upper) - 0.5,
                        std::ldexp(s.y, -upper) - 0.5, c);
    value[c] = (1 - t) * a + t * b;
  }
}

}  // namespace

Coverage classify(const ConvexPolygon& polygon, const Vec2& p, double tolerance) {
  if (polygon.empty()) return Coverage::kOutside;
  const std::vector<Vec2>& v = polygon.vertices();
  bool boundary = false;
  for (std::size_t k = 0; k < v.size(); ++k) {
    const Vec2& a = v[k];
    const Vec2& b = v[(k + 1) % v.size()];
    const Vec2 e = b - a;
    const double length = glm::length(e);
    if (length == 0.0) continue;
    const double distance = (e.x * (p.y - a.y) - e.y * (p.x - a.x)) / length;
    if (distance < -tolerance) return Coverage::kOutside;
    if (distance <= tolerance) boundary = true;
  }
  return boundary ? Coverage::kBoundary : Coverage::kInside;
}

std::vector<ReferencePixel> reference_warp(const WarpPlan& plan, const Image& source) {
  std::vector<ReferencePixel> out(static_cast<std::size_t>(plan.output_width) *
                                  static_cast<std::size_t>(std::max(plan.output_height, 0)));
  if (plan.empty) return out;
  double extent = 1.0;
  for (const Vec2& p : plan.polygon.vertices()) {
    extent = std::max({extent, std::abs(p.x), std::abs(p.y)});
  }
  const double tolerance = 1e-9 * extent;
  const std::int64_t max_x = source.width() - 1;
  const std::int64_t max_y = source.height() - 1;
  const InverseMap& m = plan.map;
  const std::vector<DoubleLevel> levels =
      plan.sampling == Sampling::kMipmap ? double_pyramid(source) : std::vector<DoubleLevel>{};
  for (int y = 0; y < plan.output_height; ++y) {
    for (int x = 0; x < plan.output_width; ++x) {
      ReferencePixel& r = out[static_cast<std::size_t>(y) * plan.output_width + x];
      r.coverage = classify(plan.polygon, Vec2(x + 0.5, y + 0.5), tolerance);
      if (r.coverage == Coverage::kOutside) continue;
      const std::int64_t X = 2 * std::int64_t{x} + 1;
      const std::int64_t Y = 2 * std::int64_t{y} + 1;
      const Int128 nu = linear(m.a, m.b, m.c, X, Y);
      const Int128 nv = linear(m.d, m.e, m.f, X, Y);
      const Int128 d = linear(m.g, m.h, m.i, X, Y);
      if (d <= 0) std::abort();  // the plan promises a positive denominator
      const std::int64_t ku = floor_div128(nu, d);
      const std::int64_t kv = floor_div128(nv, d);
      if (plan.sampling == Sampling::kMipmap) {
        mipmap_reference(m, levels, x, y, r.value);
      } else if (plan.sampling == Sampling::kNearest) {
        const Pixel& p = source.at(static_cast<int>(std::clamp<std::int64_t>(ku, 0, max_x)),
                                   static_cast<int>(std::clamp<std::int64_t>(kv, 0, max_y)));
        for (int c = 0; c < 4; ++c) r.value[c] = channel(p, c);
      } else {
        const double fx = static_cast<double>(nu - Int128{ku} * d) / static_cast<double>(d);
        const double fy = static_cast<double>(nv - Int128{kv} * d) / static_cast<double>(d);
        auto tap = [&](std::int64_t u, std::int64_t v) -> const Pixel& {
          return source.at(static_cast<int>(std::clamp<std::int64_t>(u, 0, max_x)),
                           static_cast<int>(std::clamp<std::int64_t>(v, 0, max_y)));
        };
        for (int c = 0; c < 4; ++c) {
          r.value[c] = (1 - fx) * (1 - fy) * channel(tap(ku, kv), c) +
                       fx * (1 - fy) * channel(tap(ku + 1, kv), c) +
                       (1 - fx) * fy * channel(tap(ku, kv + 1), c) +
                       fx * fy * channel(tap(ku + 1, kv + 1), c);
        }
      }
      auto level = [&](int c) { return static_cast<std::uint8_t>(std::lround(r.value[c])); };
      r.rounded = Pixel{level(0), level(1), level(2), level(3)};
    }
  }
  return out;
}

int count_mismatches(const std::vector<ReferencePixel>& reference, const Image& output,
                     Pixel sentinel, int level_tolerance, std::string* report) {
  int mismatches = 0;
  std::ostringstream text;
  for (int y = 0; y < output.height(); ++y) {
    for (int x = 0; x < output.width(); ++x) {
      const ReferencePixel& r = reference[static_cast<std::size_t>(y) * output.width() + x];
      const Pixel got = output.at(x, y);
      bool ok = false;
      bool value_ok = true;
      for (int c = 0; c < 4; ++c) {
        if (std::abs(channel(got, c) - channel(r.rounded, c)) > level_tolerance) value_ok = false;
      }
      switch (r.coverage) {
        case Coverage::kInside:
          ok = value_ok;
          break;
        case Coverage::kOutside:
          ok = got == sentinel;
          break;
        case Coverage::kBoundary:
          ok = value_ok || got == sentinel;
          break;
      }
      if (!ok) {
        if (++mismatches <= 5) {
          text << "pixel (" << x << ", " << y << ") coverage " << static_cast<int>(r.coverage)
               << " got " << int{got.r} << "," << int{got.g} << "," << int{got.b} << ","
               << int{got.a} << " expected " << int{r.rounded.r} << "," << int{r.rounded.g} << ","
               << int{r.rounded.b} << "," << int{r.rounded.a} << "\n";
        }
      }
    }
  }
  if (report != nullptr) *report = text.str();
  return mismatches;
}

Image random_image(std::mt19937& rng, int width, int height) {
  Image image(width, height);
  std::uniform_int_distribution<int> byte(0, 255);
  for (Pixel& p : image.pixels()) {
    const int a = byte(rng);
    std::uniform_int_distribution<int> colour(0, a);
    p = Pixel{static_cast<std::uint8_t>(colour(rng)), static_cast<std::uint8_t>(colour(rng)),
              static_cast<std::uint8_t>(colour(rng)), static_cast<std::uint8_t>(a)};
  }
  return image;
}

ConvexPolygon random_polygon(std::mt19937& rng, int width, int height) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const ConvexPolygon rectangle = ConvexPolygon::rectangle(0.0, 0.0, width, height);
  switch (std::uniform_int_distribution<int>(0, 2)(rng)) {
    case 0:
      return rectangle;
    case 1: {
      ConvexPolygon cut = rectangle;
      for (int k = 0; k < 3; ++k) {
        // A line through a random interior point, keeping the side of the centre.
        const Vec2 point(unit(rng) * width, unit(rng) * height);
        const double angle = 6.283185307179586 * unit(rng);
        Vec3 line(std::cos(angle), std::sin(angle), 0.0);
        line.z = -(line.x * point.x + line.y * point.y);
        if (line.x * 0.5 * width + line.y * 0.5 * height + line.z < 0.0) line = -line;
        const ConvexPolygon next = clip_to_half_plane(cut, line);
        if (next.area() > 0.2 * width * height) cut = next;
      }
      return cut;
    }
    default: {
      std::vector<Vec2> points;
      for (int k = 0; k < 8; ++k) points.emplace_back(unit(rng) * width, unit(rng) * height);
      return ConvexPolygon::from_vertices(convex_hull(points));
    }
  }
}

Mat3 rotation_about(double degrees, double cx, double cy) {
  const double t = degrees * 3.14159265358979323846 / 180.0;
  return translation_matrix(cx, cy) *
         mat3_from_rows({std::cos(t), -std::sin(t), 0.0}, {std::sin(t), std::cos(t), 0.0},
                        {0.0, 0.0, 1.0}) *
         translation_matrix(-cx, -cy);
}

}  // namespace oflab::testing

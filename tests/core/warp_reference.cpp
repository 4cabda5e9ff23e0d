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
      if (plan.sampling == Sampling::kNearest) {
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

}  // namespace oflab::testing

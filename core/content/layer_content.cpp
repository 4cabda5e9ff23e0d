// Layer contents: the procedural brick material and the facade impostor (see
// core/content/layer_content.h).
#include "content/layer_content.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "content/depth_span.h"
#include "flow/named_values.h"
#include "image/scan_conversion.h"
#include "image/sse41_clones.h"
#include "image/thread_pool.h"

namespace oflab {
namespace {

// content_unit_cost: one shaded sample and one impostor fragment in pixels of a perspective
// warp, measured by oflab-bench (content/<kind>/cost-per-unit, median unit_cost of nine
// repetitions: 109.5 and 15.6) on the development machine.
constexpr double kShadedSampleCost = 110.0;
constexpr double kImpostorFragmentCost = 15.5;

// Every kind with its name, in the order of the enum.
constexpr NamedValue<ContentKind> kNames[] = {{ContentKind::kTexture, "texture"},
                                              {ContentKind::kShaded, "shaded"},
                                              {ContentKind::kImpostor, "impostor"}};

const ContentMaterial kBrick{{0.62, 0.27, 0.18}, 0.15, 16.0};
const ContentMaterial kMortar{{0.66, 0.64, 0.60}, 0.05, 8.0};

}  // namespace

double specular_power(double c, double shininess) {
  double power = 1.0;  // 2^squarings, exactly
  int squarings = 0;
  while (power < shininess && squarings < 8) power *= 2.0, ++squarings;
  if (power != shininess) return std::pow(c, shininess);
  for (int k = 0; k < squarings; ++k) c *= c;
  return c;
}

namespace {

// Linear colour (unclamped) of `m` at viewer-frame point x with unit normal n, light l (unit).
inline __attribute__((always_inline)) Vec3 lit(const ContentMaterial& m, const Vec3& n,
                                               const Vec3& x, const Vec3& l) {
  const Vec3 v = glm::normalize(-x);
  const Vec3 h = glm::normalize(l + v);
  const double diffuse = std::max(0.0, glm::dot(n, l));
  const double spec =
      diffuse > 0.0 ? specular_power(std::max(0.0, glm::dot(n, h)), m.shininess) : 0.0;
  return m.albedo * (kContentAmbient + kContentDiffuse * diffuse) + Vec3(m.specular * spec);
}

std::uint8_t to_byte(double c) {
  return static_cast<std::uint8_t>(std::lround(255.0 * std::clamp(c, 0.0, 1.0)));
}

// The plane's frame: texel <-> viewer-frame point, and the ray of a pixel.
struct PlaneFrame {
  PlaneFrame(const Camera& c, const PlanePose& pose) : camera(c) {
    const PlaneAxes a = plane_axes(pose);
    right = a.right;
    up = a.up;
    front = -a.normal;
    centre = pose.point;
    texel = Vec2(pose.size.x / pose.texture_size.x, pose.size.y / pose.texture_size.y);
    half = 0.5 * Vec2(pose.texture_size);
  }
  // Viewer-frame point of plane coordinates (s right, t up, h towards the front).
  Vec3 point(double s, double t, double h = 0.0) const {
    return centre + s * right + t * up + h * front;
  }
  // The ray through pixel point p (top-left pixels), Z = 1.
  Vec3 ray(const Vec2& p) const {
    return Vec3((p.x - camera.cx) / camera.focal_px, (p.y - camera.cy) / camera.focal_px, 1.0);
  }
  const Camera& camera;
  Vec3 right, up, front, centre;
  Vec2 texel;  // world units per texel along u and v
  Vec2 half;   // texture centre, texels
};

// The covered box of a region and the pixels of a layer over it.
struct LayerBox {
  int x0 = 0, y0 = 0, width = 0, height = 0;
};

// `cleared` false leaves the layer's pixels for the caller to clear (to Pixel{}).
LayerBox prepare_layer(const ConvexPolygon& region, WarpedLayer& out, bool cleared = true) {
  LayerBox box;
  if (!region.empty()) {
    const BoundingBox b = region.bounds();
    box.x0 = static_cast<int>(std::floor(b.x_min));
    box.y0 = static_cast<int>(std::floor(b.y_min));
    box.width = static_cast<int>(std::ceil(b.x_max)) - box.x0;
    box.height = static_cast<int>(std::ceil(b.y_max)) - box.y0;
  }
  if (box.width > kMaxImageDimension || box.height > kMaxImageDimension) {
    throw std::invalid_argument("the content's layer would exceed the largest image size");
  }
  out.layer.image.reshape(box.width, box.height);
  if (cleared) out.layer.image.fill(Pixel{});
  out.layer.polygon = translated(region, -box.x0, -box.y0);
  out.offset_x = box.x0;
  out.offset_y = box.y0;
  out.stats = WarpStats{};
  return box;
}

// Sample positions within a pixel: a Hammersley set of n points, the centre for n = 1.
std::vector<Vec2> pixel_samples(int n) {
  std::vector<Vec2> out;
  for (int i = 0; i < n; ++i) {
    double radical = 0.0, weight = 0.5;
    for (unsigned k = static_cast<unsigned>(i); k; k >>= 1, weight *= 0.5) {
      if (k & 1u) radical += weight;
    }
    out.emplace_back((i + 0.5) / n, std::fmod(radical + 0.5 / n, 1.0));
  }
  return out;
}

// The tallies of a loop's bands, summed in band order.
ContentStats sum(const std::array<ContentStats, kMaxBands>& bands) {
  ContentStats total;
  for (const ContentStats& b : bands) {
    total.pixels_written += b.pixels_written;
    total.work_units += b.work_units;
  }
  return total;
}

double unit_hash(int a, int b) {
  std::uint32_t h =
      static_cast<std::uint32_t>(a) * 73856093u ^ static_cast<std::uint32_t>(b) * 19349663u;
  h ^= h >> 13;
  h *= 0x5bd1e995u;
  h ^= h >> 15;
  return (h & 0xffffu) / 65535.0;
}

// brick_at's body, inlined into the shaded rows (and so into their SSE4.1 clone).
inline __attribute__((always_inline)) BrickSample brick_sample(double x, double y) {
  constexpr double kW = 0.2, kH = 0.07, kHalfJoint = 0.008, kBevel = 0.02;
  const int row = static_cast<int>(std::floor(y / kH));
  const double shifted = x + ((row & 1) ? 0.5 * kW : 0.0);
  const int col = static_cast<int>(std::floor(shifted / kW));
  const double lu = shifted - col * kW, lv = y - row * kH;
  const double du = std::min(lu, kW - lu), dv = std::min(lv, kH - lv);
  if (std::min(du, dv) < kHalfJoint) return {kMortar, Vec2(0.0)};
  BrickSample s{kBrick, Vec2(0.0)};
  const double tint = (0.8 + 0.4 * unit_hash(row, col)) *
                      (0.92 + 0.16 * unit_hash(static_cast<int>(std::floor(200.0 * x)),
                                               static_cast<int>(std::floor(200.0 * y))));
  s.material.albedo *= tint;
  if (du - kHalfJoint < kBevel)
    s.slope.x = (lu < 0.5 * kW ? 1.0 : -1.0) * 0.8 * (1.0 - (du - kHalfJoint) / kBevel);
  if (dv - kHalfJoint < kBevel)
    s.slope.y = (lv < 0.5 * kH ? 1.0 : -1.0) * 0.8 * (1.0 - (dv - kHalfJoint) / kBevel);
  return s;
}

}  // namespace

BrickSample brick_at(double x, double y) { return brick_sample(x, y); }

namespace {

// Straight colour of one shaded sample, or false when the ray misses the texel region
// (precondition: texels not empty).
inline __attribute__((always_inline)) bool shade_sample(const PlaneFrame& f,
                                                        const Vec3& plane_vector,
                                                        const ConvexPolygon& texels,
                                                        const Vec3& light, const Vec2& p,
                                                        Vec3& colour) {
  const Vec3 r = f.ray(p);
  const double d = glm::dot(plane_vector, r);
  if (!(d > 1e-12)) return false;
  const Vec3 x = r / d;
  const Vec3 rel = x - f.centre;
  const Vec2 uv(glm::dot(rel, f.right) / f.texel.x + f.half.x,
                f.half.y - glm::dot(rel, f.up) / f.texel.y);
  if (!within_vertices(texels.vertices(), uv)) return false;
  const BrickSample b = brick_sample(uv.x * f.texel.x, uv.y * f.texel.y);
  // The slope is along u (right) and v (down): the normal leans against it.
  const Vec3 n = glm::normalize(f.front - b.slope.x * f.right + b.slope.y * f.up);
  colour += lit(b.material, n, x, light);
  return true;
}

// What every row of a shaded render shares.
struct ShadedRows {
  const PlaneFrame& f;
  const Vec3& plane_vector;
  const ConvexPolygon& texels;
  const Vec3& light;
  const std::vector<Vec2>& samples;  // offsets in a pixel
  const LayerBox& box;
};

// Shades the layer's pixels in rows [begin, end), tallying them in `stats`
// (OFLAB_SSE41_CLONES: the same values). The tallies are kept in locals and added once: the
// bands' slots share cache lines, and a pixel store may alias them.
OFLAB_SSE41_CLONES void shade_rows(const ShadedRows& r, int begin, int end, WarpedLayer& out,
                                   ContentStats& stats) {
  const bool any = !r.texels.empty();  // else no sample hits (shade_sample's precondition)
  ScanConverter scan(out.layer.polygon, r.box.width, r.box.height);
  scan.clip_rows(begin, end);
  PixelSpan span;
  std::int64_t work = 0, written = 0;
  while (scan.next(span)) {
    Pixel* row = out.layer.image.row(span.y);
    for (int x = span.x_begin; x < span.x_end; ++x) {
      Vec3 colour(0.0);
      int hits = 0;
      for (const Vec2& s : r.samples) {
        const Vec2 p(r.box.x0 + x + s.x, r.box.y0 + span.y + s.y);
        hits += any && shade_sample(r.f, r.plane_vector, r.texels, r.light, p, colour) ? 1 : 0;
      }
      work += static_cast<std::int64_t>(r.samples.size());
      if (hits == 0) continue;
      const double coverage = static_cast<double>(hits) / r.samples.size();
      const Vec3 c = colour / static_cast<double>(r.samples.size());  // premultiplied
      row[x] = Pixel{to_byte(c.r), to_byte(c.g), to_byte(c.b), to_byte(coverage)};
      ++written;
    }
  }
  stats.work_units += work;
  stats.pixels_written += written;
}

ContentStats render_shaded(const LayerContent& content, const Camera& camera, const PlanePose& pose,
                           const ConvexPolygon& texels, const ConvexPolygon& region,
                           WarpedLayer& out) {
  const LayerBox box = prepare_layer(region, out);
  const PlaneFrame f(camera, pose);
  const Vec3 plane_vec = plane_vector(pose);
  const Vec3 light = glm::normalize(content.light);
  const std::vector<Vec2> samples = pixel_samples(content.quality);
  // Bands of rows on the worker threads (core/image/thread_pool.h), each with its tally.
  std::array<ContentStats, kMaxBands> band_stats{};
  const int min_rows = std::max(4, 4096 / std::max(1, box.width * content.quality));
  for_each_band(box.height, min_rows, [&](int band, int begin, int end) {
    const ShadedRows rows{f, plane_vec, texels, light, samples, box};
    shade_rows(rows, begin, end, out, band_stats[static_cast<std::size_t>(band)]);
  });
  const ContentStats stats = sum(band_stats);
  out.stats.pixels_written = stats.pixels_written;
  return stats;
}

// ---- The facade impostor ----

// The five visible faces of a box [s0, s1] x [t0, t1] x [0, depth] standing on the wall
// (its back lies on the wall and is never seen), offset by h0 from the wall.
void add_box(std::vector<FacadeFace>& faces, double s0, double t0, double s1, double t1, double h0,
             double depth, FacadePart m) {
  const double h1 = h0 + depth;
  faces.push_back(
      {{Vec3(s0, t0, h1), Vec3(s1, t0, h1), Vec3(s1, t1, h1), Vec3(s0, t1, h1)}, Vec3(0, 0, 1), m});
  faces.push_back({{Vec3(s0, t0, h0), Vec3(s0, t1, h0), Vec3(s0, t1, h1), Vec3(s0, t0, h1)},
                   Vec3(-1, 0, 0),
                   m});
  faces.push_back(
      {{Vec3(s1, t0, h0), Vec3(s1, t1, h0), Vec3(s1, t1, h1), Vec3(s1, t0, h1)}, Vec3(1, 0, 0), m});
  faces.push_back({{Vec3(s0, t0, h0), Vec3(s1, t0, h0), Vec3(s1, t0, h1), Vec3(s0, t0, h1)},
                   Vec3(0, -1, 0),
                   m});
  faces.push_back(
      {{Vec3(s0, t1, h0), Vec3(s1, t1, h0), Vec3(s1, t1, h1), Vec3(s0, t1, h1)}, Vec3(0, 1, 0), m});
}

// One window of a facade cell centred at (cs, ct) with cell size (cw, ch): glass, a frame
// of four bars, a sill, and with `balcony` a slab, a top rail and five posts.
void add_window(std::vector<FacadeFace>& faces, double cs, double ct, double cw, double ch,
                bool balcony) {
  const double unit = std::min(cw, ch), ww = 0.25 * cw, wh = 0.3 * ch, bar = 0.06 * unit;
  const double s0 = cs - ww, s1 = cs + ww, t0 = ct - wh, t1 = ct + wh, lift = 0.004 * unit;
  faces.push_back({{Vec3(s0, t0, lift), Vec3(s1, t0, lift), Vec3(s1, t1, lift), Vec3(s0, t1, lift)},
                   Vec3(0, 0, 1),
                   FacadePart::kGlass});
  const double fd = 0.05 * unit;
  add_box(faces, s0 - bar, t1, s1 + bar, t1 + bar, 0.0, fd, FacadePart::kFrame);
  add_box(faces, s0 - bar, t0 - bar, s1 + bar, t0, 0.0, fd, FacadePart::kFrame);
  add_box(faces, s0 - bar, t0, s0, t1, 0.0, fd, FacadePart::kFrame);
  add_box(faces, s1, t0, s1 + bar, t1, 0.0, fd, FacadePart::kFrame);
  add_box(faces, s0 - 2 * bar, t0 - 2 * bar, s1 + 2 * bar, t0 - bar, 0.0, 0.15 * unit,
          FacadePart::kStone);
  if (!balcony) return;
  const double b0 = cs - 0.4 * cw, b1 = cs + 0.4 * cw, base = ct - 0.5 * ch + 0.02 * ch;
  const double out = 0.45 * unit, rail = 0.35 * unit;
  add_box(faces, b0, base, b1, base + bar, 0.0, out, FacadePart::kStone);
  add_box(faces, b0, base + rail, b1, base + rail + 0.5 * bar, out - bar, bar, FacadePart::kRail);
  for (int k = 0; k < 5; ++k) {
    const double s = b0 + (b1 - b0) * (k + 0.5) / 5.0;
    add_box(faces, s - 0.25 * bar, base + bar, s + 0.25 * bar, base + rail, out - bar, bar,
            FacadePart::kRail);
  }
}

}  // namespace

std::vector<FacadeFace> facade_faces(const Vec2& size, int detail) {
  const int storeys = 1 + detail, bays = 1 + 2 * detail;
  const double w = size.x, h = size.y, cw = w / bays, ch = h / storeys;
  // The faces' count, as add_window adds them (a window: glass and five boxes of five faces;
  // a balcony on every second storey: seven boxes), reserved at once: a street re-renders
  // facades of about a thousand faces every frame, and growing the vector copied them about
  // twice over (3 % of the engine's frame on the street).
  constexpr int kWindowFaces = 1 + 5 * 5, kBalconyFaces = 7 * 5;
  std::vector<FacadeFace> faces;
  faces.reserve(static_cast<std::size_t>(1 + storeys * bays * kWindowFaces +
                                         storeys / 2 * bays * kBalconyFaces));
  faces.push_back({{Vec3(-0.5 * w, -0.5 * h, 0), Vec3(0.5 * w, -0.5 * h, 0),
                    Vec3(0.5 * w, 0.5 * h, 0), Vec3(-0.5 * w, 0.5 * h, 0)},
                   Vec3(0, 0, 1),
                   FacadePart::kWall});
  for (int st = 0; st < storeys; ++st) {
    for (int b = 0; b < bays; ++b) {
      add_window(faces, -0.5 * w + (b + 0.5) * cw, -0.5 * h + (st + 0.5) * ch, cw, ch, st % 2 == 1);
    }
  }
  return faces;
}

namespace {

// Keeps the part of a viewer-frame quad at Z >= z_min (Sutherland-Hodgman) in out[0 .. n - 1]
// (at most 5 vertices); returns n.
int clip_near(const std::array<Vec3, 4>& in, double z_min, std::array<Vec3, 5>& out) {
  int n = 0;
  for (std::size_t k = 0; k < in.size(); ++k) {
    const Vec3& a = in[k];
    const Vec3& b = in[next_vertex(k, in.size())];
    if (a.z >= z_min) out[n++] = a;
    if ((a.z >= z_min) != (b.z >= z_min)) out[n++] = a + (b - a) * ((z_min - a.z) / (b.z - a.z));
  }
  return n;
}

// The edges of a convex region (layer pixels) as lines (a, b, c), a x + b y + c >= 0 on the
// region's side: found once for all the faces of a render.
std::vector<Vec3> region_lines(const ConvexPolygon& region) {
  const std::vector<Vec2>& v = region.vertices();
  Vec2 inside(0.0);
  for (const Vec2& p : v) inside += p / static_cast<double>(v.size());
  std::vector<Vec3> lines;
  for (std::size_t k = 0; k < v.size(); ++k) {
    const Vec2& a = v[k];
    const Vec2& b = v[next_vertex(k, v.size())];
    Vec3 line(a.y - b.y, b.x - a.x, a.x * b.y - a.y * b.x);
    if (line.x * inside.x + line.y * inside.y + line.z < 0.0) line = -line;
    lines.push_back(line);
  }
  return lines;
}

// The polygon clipped to the region of `lines` (region_lines), edge by edge. Shortcuts with
// the same result: a polygon with every vertex strictly outside one edge is clipped away
// whole (empty), and one with no vertex outside any edge (most of a facade's faces) is
// returned as it is (clip_to_half_plane keeps such a polygon vertex for vertex).
ConvexPolygon clip_to_region(ConvexPolygon polygon, const std::vector<Vec3>& lines) {
  bool within = true;
  for (const Vec3& line : lines) {
    bool all_outside = true;
    for (const Vec2& p : polygon.vertices()) {
      const double side = line.x * p.x + line.y * p.y + line.z;
      within &= side >= 0.0;
      all_outside &= side < 0.0;
    }
    if (all_outside) return ConvexPolygon();
  }
  if (within) return polygon;
  for (std::size_t k = 0; k < lines.size() && !polygon.empty(); ++k) {
    polygon = clip_to_half_plane(polygon, lines[k]);
  }
  return polygon;
}

// One face as the layer sees it: its pixel shape (layer pixels), flat colour, and 1/Z as an
// affine function of the pixel (c0 + a x + b y at pixel centres).
struct FaceRaster {
  ConvexPolygon shape;
  Pixel colour;
  double a = 0.0, b = 0.0, c0 = 0.0;
  int first_row = 0, end_row = 0;  // the layer rows the shape may cover: [first_row, end_row)
};

// The face's raster, or false when it is seen from behind or covers no part of the region.
bool face_raster(const FacadeFace& face, const PlaneFrame& f, const Vec3& light,
                 const LayerBox& box, const std::vector<Vec3>& region, FaceRaster& raster) {
  std::array<Vec3, 4> world;
  for (std::size_t k = 0; k < world.size(); ++k) {
    const Vec3& c = face.corners[k];
    world[k] = f.point(c.x, c.y, c.z);
  }
  const Vec3 n =
      glm::normalize(face.normal.x * f.right + face.normal.y * f.up + face.normal.z * f.front);
  if (glm::dot(n, world[0]) >= 0.0) return false;  // seen from behind
  std::array<Vec3, 5> front;
  const int count = clip_near(world, 1e-6, front);
  if (count < 3) return false;
  std::vector<Vec2> pixels;
  pixels.reserve(static_cast<std::size_t>(count));
  for (int k = 0; k < count; ++k) {
    const Vec3& p = front[static_cast<std::size_t>(k)];
    pixels.emplace_back(f.camera.focal_px * p.x / p.z + f.camera.cx - box.x0,
                        f.camera.focal_px * p.y / p.z + f.camera.cy - box.y0);
  }
  raster.shape = clip_to_region(make_polygon_unchecked(std::move(pixels)), region);
  if (raster.shape.empty()) return false;
  const ScanConverter rows(raster.shape, box.width, box.height);
  raster.first_row = rows.first_row();
  raster.end_row = rows.end_row();
  Vec3 centre(0.0);
  for (const Vec3& p : world) centre += 0.25 * p;
  const Vec3 c = lit(facade_material(face.part), n, centre, light);
  raster.colour = Pixel{to_byte(c.r), to_byte(c.g), to_byte(c.b), 255};
  // 1/Z along the ray (x, y, 1) of the face's plane n.X = e is n.(x, y, 1) / e: affine in pixels.
  const double e = glm::dot(n, world[0]), k = 1.0 / (f.camera.focal_px * e);
  raster.a = n.x * k;
  raster.b = n.y * k;
  raster.c0 =
      n.z / e + raster.a * (box.x0 + 0.5 - f.camera.cx) + raster.b * (box.y0 + 0.5 - f.camera.cy);
  return true;
}

// Rasterises rows [begin, end) of one face into the layer with the depth buffer (1/Z,
// larger is nearer). A pixel's first store (the layer starts transparent, a face's colour is
// opaque) is counted in stats.pixels_written.
void draw_face_rows(const FaceRaster& face, const LayerBox& box, int begin, int end,
                    std::vector<float>& depth, WarpedLayer& out, ContentStats& stats) {
  if (face.end_row <= begin || face.first_row >= end) return;  // not in this band
  ScanConverter scan(face.shape, box.width, box.height);
  scan.clip_rows(begin, end);
  PixelSpan span;
  std::int64_t written = 0, work = 0;
  while (scan.next(span)) {
    if (span.x_end <= span.x_begin) continue;
    work += span.x_end - span.x_begin;
    const DepthRow plane{face.a, face.c0, face.b * span.y};
    written += draw_depth_span(plane, face.colour, span.x_begin, span.x_end,
                               depth.data() + static_cast<std::size_t>(span.y) * box.width,
                               out.layer.image.row(span.y));
  }
  stats.work_units += work;
  stats.pixels_written += written;
}

// Every face's rows [begin, end), in face order (OFLAB_SSE41_CLONES: the same values).
OFLAB_SSE41_CLONES void draw_faces(const std::vector<FaceRaster>& faces, const LayerBox& box,
                                   int begin, int end, std::vector<float>& depth, WarpedLayer& out,
                                   ContentStats& stats) {
  for (const FaceRaster& face : faces) draw_face_rows(face, box, begin, end, depth, out, stats);
}

ContentStats render_impostor(const LayerContent& content, const Camera& camera,
                             const PlanePose& pose, const ConvexPolygon& region, WarpedLayer& out) {
  const LayerBox box = prepare_layer(region, out, false);  // cleared band by band below
  const PlaneFrame f(camera, pose);
  const Vec3 light = glm::normalize(content.light);
  // The faces' rasters in bands of faces on the worker threads, kept in face order.
  const std::vector<FacadeFace> all = facade_faces(pose.size, content.quality);
  const std::vector<Vec3> region_edges = region_lines(out.layer.polygon);
  std::array<std::vector<FaceRaster>, kMaxBands> banded;
  for_each_band(static_cast<int>(all.size()), 64, [&](int band, int begin, int end) {
    for (int k = begin; k < end; ++k) {
      FaceRaster raster;
      if (face_raster(all[static_cast<std::size_t>(k)], f, light, box, region_edges, raster))
        banded[static_cast<std::size_t>(band)].push_back(std::move(raster));
    }
  });
  std::vector<FaceRaster> faces;
  for (std::vector<FaceRaster>& b : banded) {
    for (FaceRaster& r : b) faces.push_back(std::move(r));
  }
  // The depth buffer's memory is kept from render to render (a camera-sized buffer is
  // megabytes a frame to map and fault in); each band clears its own rows, as it does the
  // layer's, just before drawing them.
  thread_local std::vector<float> kept_depth;
  std::vector<float>& depth = kept_depth;  // the bands, on other threads, use this thread's
  depth.resize(static_cast<std::size_t>(box.width) * box.height);
  // Bands of rows on the worker threads (core/image/thread_pool.h): every band draws every
  // face in the same order over its own rows, so each pixel's depth test is the same.
  std::array<ContentStats, kMaxBands> band_stats{};
  const int min_rows = std::max(8, 16384 / std::max(box.width, 1));
  for_each_band(box.height, min_rows, [&](int band, int begin, int end) {
    ContentStats& stats = band_stats[static_cast<std::size_t>(band)];
    const std::size_t first = static_cast<std::size_t>(begin) * box.width;
    const std::size_t last = static_cast<std::size_t>(end) * box.width;
    if (first < last) {
      std::fill(depth.begin() + first, depth.begin() + last, 0.0f);
      std::fill(out.layer.image.row(begin), out.layer.image.row(begin) + (last - first), Pixel{});
    }
    draw_faces(faces, box, begin, end, depth, out, stats);
  });
  const ContentStats stats = sum(band_stats);
  out.stats.pixels_written = stats.pixels_written;
  return stats;
}

}  // namespace

const char* content_name(ContentKind kind) { return name_of_value(kNames, kind, "?"); }

bool parse_content(const std::string& text, ContentKind* kind) {
  return parse_named_value(kNames, text, kind);
}

std::vector<ContentKind> content_kinds() {
  std::vector<ContentKind> out;
  for (const NamedValue<ContentKind>& n : kNames) out.push_back(n.value);
  return out;
}

std::string content_name_list(const std::string& separator) {
  return named_value_list(kNames, separator);
}

std::string content_problem(const LayerContent& content) {
  if (content.quality < 1 || content.quality > kMaxContentQuality) {
    return "quality " + std::to_string(content.quality) + " is outside 1 .. " +
           std::to_string(kMaxContentQuality);
  }
  const Vec3& l = content.light;
  if (!std::isfinite(l.x) || !std::isfinite(l.y) || !std::isfinite(l.z) || glm::length(l) == 0.0) {
    return "light must be a finite, non-zero direction";
  }
  return "";
}

bool content_is_lit(const LayerContent& content) { return content.kind != ContentKind::kTexture; }

double shaded_samples(const LayerContent& content, double layer_pixels) {
  return content.kind == ContentKind::kShaded ? content.quality * layer_pixels : 0.0;
}

std::string plane_shaded_samples_problem(const LayerContent& content, const Camera& camera) {
  std::ostringstream subject;
  subject << "shaded content at quality " << content.quality << " on a " << camera.width << " x "
          << camera.height << " px camera";
  return shaded_samples_problem(
      shaded_samples(content, static_cast<double>(camera.width) * camera.height), subject.str());
}

std::string shaded_samples_problem(double samples, const std::string& subject) {
  const Limit& limit = limits::kShadedSamples;
  if (limit.allows(samples)) return "";
  std::ostringstream text;
  text << subject << " may take " << static_cast<long long>(samples)
       << " shaded samples a frame, more than " << static_cast<long long>(limit.maximum) << " (the "
       << limit.what << " limit)";
  return text.str();
}

ContentStats render_content(const LayerContent& content, const Camera& camera,
                            const PlanePose& pose, const ConvexPolygon& texel_region,
                            const ConvexPolygon& image_region, WarpedLayer& out) {
  switch (content.kind) {
    case ContentKind::kShaded:
      return render_shaded(content, camera, pose, texel_region, image_region, out);
    case ContentKind::kImpostor:
      return render_impostor(content, camera, pose, image_region, out);
    case ContentKind::kTexture:
      break;
  }
  throw std::invalid_argument("render_content: texture content is drawn by a warp");
}

ContentMaterial facade_material(FacadePart part) {
  switch (part) {
    case FacadePart::kWall:
      return {{0.80, 0.68, 0.52}, 0.10, 16.0};
    case FacadePart::kGlass:
      return {{0.15, 0.22, 0.30}, 0.60, 64.0};
    case FacadePart::kFrame:
      return {{0.93, 0.93, 0.90}, 0.20, 32.0};
    case FacadePart::kStone:
      return {{0.70, 0.70, 0.68}, 0.10, 16.0};
    case FacadePart::kRail:
      break;
  }
  return {{0.20, 0.20, 0.22}, 0.40, 32.0};
}

double content_unit_cost(ContentKind kind) {
  switch (kind) {
    case ContentKind::kShaded:
      return kShadedSampleCost;
    case ContentKind::kImpostor:
      return kImpostorFragmentCost;
    case ContentKind::kTexture:
      break;
  }
  return 1.0;
}

double shading_change(const LayerContent& content, const PlanePose& rendered,
                      const PlanePose& now) {
  if (!content_is_lit(content)) return 0.0;
  const Camera unused;
  const PlaneFrame a(unused, rendered), b(unused, now);
  const Vec3 light = glm::normalize(content.light);
  std::vector<Vec3> facings = {Vec3(0, 0, 1)};
  std::vector<ContentMaterial> materials = {kBrick, kMortar};
  if (content.kind == ContentKind::kImpostor) {
    facings = {Vec3(0, 0, 1), Vec3(1, 0, 0), Vec3(-1, 0, 0), Vec3(0, 1, 0), Vec3(0, -1, 0)};
    materials.clear();
    for (FacadePart part : kFacadeParts) materials.push_back(facade_material(part));
  }
  // A white surface's light depends on a material only through its specular terms: the
  // materials with the same ones give the same greys (the wall's and the stone's).
  std::vector<ContentMaterial> kinds;
  for (const ContentMaterial& m : materials) {
    const bool seen = std::any_of(kinds.begin(), kinds.end(), [&](const ContentMaterial& k) {
      return k.specular == m.specular && k.shininess == m.shininess;
    });
    if (!seen) kinds.push_back(m);
  }
  // lit() of a white material, its geometry (diffuse factor and N.H) found once per point and
  // facing, the same operations in the same order: the same greys.
  struct Geometry {
    double base = 0.0;  // ambient + diffuse
    double nh = 0.0;    // (N.H)+
    bool lit = false;   // diffuse > 0: the specular term counts
  };
  const auto geometry = [&](const PlaneFrame& f, const Vec3& facing, double s, double t) {
    const Vec3 n = facing.x * f.right + facing.y * f.up + facing.z * f.front;
    const Vec3 v = glm::normalize(-f.point(s, t));
    const Vec3 h = glm::normalize(light + v);
    const double diffuse = std::max(0.0, glm::dot(n, light));
    return Geometry{kContentAmbient + kContentDiffuse * diffuse, std::max(0.0, glm::dot(n, h)),
                    diffuse > 0.0};
  };
  const auto grey = [](const Geometry& g, const ContentMaterial& m) {
    const double spec = g.lit ? specular_power(g.nh, m.shininess) : 0.0;
    return 255.0 * std::clamp(1.0 * g.base + m.specular * spec, 0.0, 1.0);
  };
  double worst = 0.0;
  for (int i = 0; i < 5; ++i) {
    for (int j = 0; j < 5; ++j) {
      const double s = (i / 4.0 - 0.5) * rendered.size.x, t = (j / 4.0 - 0.5) * rendered.size.y;
      for (const Vec3& facing : facings) {
        const Geometry then = geometry(a, facing, s, t), current = geometry(b, facing, s, t);
        for (const ContentMaterial& m : kinds) {
          worst = std::max(worst, std::abs(grey(then, m) - grey(current, m)));
        }
      }
    }
  }
  return worst;
}

}  // namespace oflab

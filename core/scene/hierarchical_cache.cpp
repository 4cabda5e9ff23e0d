// Shade et al.'s hierarchical image cache on a scene (core/scene/hierarchical_cache.h).
#include "scene/hierarchical_cache.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <stdexcept>

#include "engine/wall_clock.h"
#include "flow/limits.h"
#include "flow/reprojection.h"
#include "image/composite.h"
#include "image/thread_pool.h"
#include "scene/depth_reprojection.h"

namespace oflab {
namespace {

using Clock = WallClock;

constexpr double kPi = 3.14159265358979323846;
// A node image's pixel counts as covering when at least half opaque.
constexpr std::uint8_t kCoverAlpha = 128;

// The convex hull of `points` (Andrew's monotone chain), clockwise on screen.
std::vector<Vec2> convex_hull(std::vector<Vec2> p) {
  std::sort(p.begin(), p.end(),
            [](const Vec2& a, const Vec2& b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
  if (p.size() < 3) return p;
  const auto cross = [](const Vec2& o, const Vec2& a, const Vec2& b) {
    return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
  };
  std::vector<Vec2> hull(2 * p.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    while (k >= 2 && cross(hull[k - 2], hull[k - 1], p[i]) <= 0) --k;
    hull[k++] = p[i];
  }
  for (std::size_t i = p.size() - 1, t = k + 1; i > 0; --i) {
    while (k >= t && cross(hull[k - 2], hull[k - 1], p[i - 1]) <= 0) --k;
    hull[k++] = p[i - 1];
  }
  hull.resize(k - 1);
  return hull;
}

// Writes `value` into `labels` (row-major, width x height) at every pixel that `image`,
// placed with its top-left pixel at (offset_x, offset_y), covers at kCoverAlpha or more.
void label_covered(const Image& image, int offset_x, int offset_y, int width, int height, int value,
                   std::vector<int>& labels) {
  for (int y = 0; y < image.height(); ++y) {
    const int ly = y + offset_y;
    if (ly < 0 || ly >= height) continue;
    for (int x = 0; x < image.width(); ++x) {
      const int lx = x + offset_x;
      if (lx >= 0 && lx < width && image.at(x, y).a >= kCoverAlpha) {
        labels[static_cast<std::size_t>(ly) * width + lx] = value;
      }
    }
  }
}

// The camera whose image is the rectangle of `camera`'s pixels with top-left corner
// (x0, y0) and the given size.
Camera sub_camera(const Camera& camera, int x0, int y0, int width, int height) {
  Camera c = camera;
  c.cx -= x0;
  c.cy -= y0;
  c.width = width;
  c.height = height;
  return c;
}

// The part of a node image (width x height, top-left at (x0, y0) of the frame) its bounding
// box's projected hull covers, in the image's pixels: the whole image when the hull is
// degenerate or was not computed (fewer than 3 points).
ConvexPolygon hull_region(const std::vector<Vec2>& hull, int x0, int y0, int width, int height) {
  std::vector<Vec2> local;
  for (const Vec2& v : hull) local.push_back(v - Vec2(x0, y0));
  ConvexPolygon region = ConvexPolygon::rectangle(0, 0, width, height);
  if (local.size() >= 3) {
    try {
      region = ConvexPolygon::from_vertices(local);
    } catch (const std::invalid_argument&) {
      // A degenerate hull: the whole rectangle.
    }
  }
  return region;
}
// The part of `region` (pixels of a node image) that `to_frame` maps inside the frame
// [0, width] x [0, height]: each frame edge's half-plane pulled back through the homography
// (line l in the frame is H^T l in the image, where H's denominator is positive). Where the
// denominator is not positive the warp refuses the image anyway, so the region is kept whole.
ConvexPolygon in_frame_part(const ConvexPolygon& region, const Mat3& to_frame, int width,
                            int height) {
  for (const Vec2& v : region.vertices()) {
    if (!(homography_denominator(to_frame, v) > 0.0)) return region;
  }
  // l . (H p) = (H^T l) . p, and the positive denominator keeps the side.
  const Mat3 pull = glm::transpose(to_frame);
  ConvexPolygon part = region;
  for (const Vec3& line : {Vec3(1, 0, 0), Vec3(-1, 0, width), Vec3(0, 1, 0), Vec3(0, -1, height)}) {
    part = clip_to_half_plane(part, pull * line);
  }
  return part;
}

}  // namespace

std::string cache_settings_problem(const CacheSettings& s) {
  if (std::string p = limits::kCacheAngle.problem(s.angle_deg); !p.empty()) {
    return "cache angle: " + p;
  }
  if (std::string p = limits::kCacheNodePolygons.problem(s.max_node_polygons); !p.empty()) {
    return "node polygons: " + p;
  }
  if (std::string p = limits::kSafetyRadius.problem(s.safety_radius); !p.empty()) {
    return "safety radius: " + p;
  }
  return "";
}

struct HierarchicalCache::NodeState {
  bool valid = false;        // `image` is a cached image that may be reused
  Layer image;               // the node's fragments as rendered, on its quad
  int x0 = 0, y0 = 0;        // top-left of `image` in the pixels of the frame it was rendered in
  std::vector<int> surface;  // per pixel of `image`: index into planes (-1: nothing)
  std::vector<Vec3> planes;  // plane vector of each of the node's polygons, render view
  ViewerPose view;           // the view it was rendered in
  CacheQuad quad;
  double radius = 0.0;  // the safety sphere, world units
  // This frame:
  WarpedLayer shown;   // the image as shown (warped, or as rendered at its offset)
  Mat3 to_frame{1.0};  // image pixels -> this frame's pixels
  bool reused = false;
};

HierarchicalCache::HierarchicalCache(const Scene& scene, const Camera& camera, const BspTree& bsp,
                                     const CacheSettings& settings, const CacheContext& context)
    : scene_(scene), camera_(camera), bsp_(bsp), settings_(settings), context_(context) {
  if (const std::string problem = cache_settings_problem(settings); !problem.empty()) {
    throw std::invalid_argument(problem);
  }
  threshold_ = settings.angle_deg * kPi / 180.0;
  nodes_ = group_cache_nodes(bsp, settings.max_node_polygons);
  nodes_of_polygon_.assign(scene.polygons.size(), {});
  for (std::size_t k = 0; k < nodes_.size(); ++k) {
    for (int p : nodes_[k].polygons) nodes_of_polygon_[p].push_back(static_cast<int>(k));
    states_.push_back(std::make_unique<NodeState>());
  }
  for (const Image& t : scene.textures) textures_.push_back(make_layer(t));
}

HierarchicalCache::~HierarchicalCache() = default;

void HierarchicalCache::restart() {
  for (auto& s : states_) s->valid = false;
}

double HierarchicalCache::node_radius(int k) const { return states_[k]->radius; }

HierarchicalCache::NodeRect HierarchicalCache::node_rect(int k, const ViewerPose& view,
                                                         bool cached) const {
  NodeRect r{0, 0, camera_.width, camera_.height, {}};
  if (!cached) return r;
  for (const Vec3& c : nodes_[k].corners()) {
    r.hull.push_back(centred_to_pixel(camera_, project_centred(camera_, to_view(view, c))));
  }
  r.hull = convex_hull(r.hull);
  BoundingBox box{r.hull[0].x, r.hull[0].y, r.hull[0].x, r.hull[0].y};
  for (const Vec2& v : r.hull) {
    box = {std::min(box.x_min, v.x), std::min(box.y_min, v.y), std::max(box.x_max, v.x),
           std::max(box.y_max, v.y)};
  }
  r.x0 = static_cast<int>(std::floor(box.x_min));
  r.y0 = static_cast<int>(std::floor(box.y_min));
  r.width = std::max(1, static_cast<int>(std::ceil(box.x_max)) - r.x0);
  r.height = std::max(1, static_cast<int>(std::ceil(box.y_max)) - r.y0);
  return r;
}

bool HierarchicalCache::paint_fragment(int f, const ViewerPose& view, const Camera& sub,
                                       const ViewFrustum& frustum, Image& image,
                                       std::int64_t* pixels, double* work, PlacedLayer& placed) {
  const BspFragment& fragment = bsp_.fragments()[f];
  const ScenePolygon& polygon = scene_.polygons[fragment.polygon];
  ViewPolygon piece;
  for (const Vec3& v : fragment.vertices) piece.points.push_back(to_view(view, v));
  piece.uv = fragment.uv;
  clip_to_frustum_in_place(piece, frustum);
  if (piece.empty()) return false;
  const Image& texture = scene_.textures[polygon.texture];
  const glm::ivec2 size(texture.width(), texture.height());
  LayerContent content = context_.content;
  content.kind = polygon.content;
  try {
    placed = render_clipped_piece(
        sub, content, textures_[polygon.texture], polygon_pose(polygon, view, size),
        texel_polygon(polygon_outline(polygon), size), piece, context_.sampling, pixels, work);
  } catch (const std::invalid_argument&) {
    return false;  // a sliver beyond the warps' fixed-point range: drawn as nothing
  }
  composite_over(image, placed.layer, placed.offset_x, placed.offset_y);
  return true;
}

Image HierarchicalCache::paint_fragments(int k, const ViewerPose& view,
                                         const std::vector<char>& culled, const NodeRect& at,
                                         AnimationFrame& report) {
  NodeState& s = *states_[k];
  const Camera sub = sub_camera(camera_, at.x0, at.y0, at.width, at.height);
  const ViewFrustum frustum = view_frustum(sub, context_.near, 1.0);
  Image image(at.width, at.height);
  s.surface.assign(static_cast<std::size_t>(at.width) * at.height, -1);
  s.planes.clear();
  std::vector<int> fragments = nodes_[k].fragments;
  std::sort(fragments.begin(), fragments.end(),
            [&](int a, int b) { return fragment_position_[a] < fragment_position_[b]; });
  for (int f : fragments) {
    const ScenePolygon& polygon = scene_.polygons[bsp_.fragments()[f].polygon];
    PlacedLayer placed;
    if (culled[bsp_.fragments()[f].polygon] ||
        !paint_fragment(f, view, sub, frustum, image, &report.pixels_written, &report.model_work,
                        placed)) {
      continue;
    }
    // Which surface each pixel shows: the last fragment painted over it (back to front).
    const int plane = static_cast<int>(s.planes.size());
    s.planes.push_back(
        plane_vector_of(to_view(view, polygon.centre), direction_to_view(view, polygon.front)));
    label_covered(placed.layer.image, placed.offset_x, placed.offset_y, at.width, at.height, plane,
                  s.surface);
  }
  return image;
}

Image HierarchicalCache::exact_frame(const ViewerPose& view, const std::vector<char>& culled) {
  const ViewFrustum frustum = view_frustum(camera_, context_.near, 1.0);
  Image image(camera_.width, camera_.height);
  std::int64_t pixels = 0;
  double work = 0.0;
  for (int f : order_) {
    PlacedLayer placed;
    if (!culled[bsp_.fragments()[f].polygon]) {
      paint_fragment(f, view, camera_, frustum, image, &pixels, &work, placed);
    }
  }
  return image;
}

void HierarchicalCache::render_node(int k, const ViewerPose& view, const std::vector<char>& culled,
                                    bool cached, AnimationFrame& report) {
  NodeState& s = *states_[k];
  const CacheNode& node = nodes_[k];
  const NodeRect at = node_rect(k, view, cached);
  Image image = paint_fragments(k, view, culled, at, report);
  s.image = make_layer(std::move(image), hull_region(at.hull, at.x0, at.y0, at.width, at.height));
  s.x0 = at.x0;
  s.y0 = at.y0;
  s.view = view;
  s.valid = cached;
  s.reused = false;
  s.to_frame = translation_matrix(at.x0, at.y0);
  s.shown.layer = s.image;
  s.shown.offset_x = at.x0;
  s.shown.offset_y = at.y0;
  if (cached) {
    s.quad = cache_quad(eye_position(view), node.centre());
    s.radius = settings_.safety_radius > 0.0 ? settings_.safety_radius
                                             : safety_radius(s.quad, node.corners(), threshold_);
  }
}

bool HierarchicalCache::warp_node(int k, const ViewerPose& current, AnimationFrame& report) {
  NodeState& s = *states_[k];
  const Vec3 m =
      plane_vector_of(to_view(s.view, s.quad.centre), direction_to_view(s.view, s.quad.normal));
  const Mat3 h = plane_induced_homography(camera_, viewer_step(s.view, current), m);
  s.to_frame = h * translation_matrix(s.x0, s.y0);
  WarpOptions options;
  options.sampling = context_.sampling;
  // Only the part of the image that lands in the frame is warped: the image keeps its whole
  // region for later frames, the warp gets it clipped to the frame's preimage.
  const ConvexPolygon region = s.image.polygon;
  s.image.polygon = in_frame_part(region, s.to_frame, camera_.width, camera_.height);
  try {
    warp_layer_reusing(s.image, s.to_frame, s.shown, options);
  } catch (const std::invalid_argument&) {
    s.image.polygon = region;
    return false;
  }
  s.image.polygon = region;
  report.pixels_written += s.shown.stats.pixels_written;
  report.model_work += s.shown.stats.pixels_written * kPerspectiveWarpCost;
  s.reused = true;
  return true;
}

HierarchicalCache::VertexErrors HierarchicalCache::vertex_errors(int k,
                                                                 const ViewerPose& current) const {
  const NodeState& s = *states_[k];
  VertexErrors e;
  for (int f : nodes_[k].fragments) {
    for (const Vec3& v : bsp_.fragments()[f].vertices) {
      const Vec3 exact = to_view(current, v);
      const Vec3 shown = to_view(current, point_on_quad(s.quad, v));
      if (exact.z < context_.near || shown.z < context_.near) continue;
      e.measured = std::max(e.measured, double(glm::length(project_centred(camera_, exact) -
                                                           project_centred(camera_, shown))));
      e.estimated = std::max(e.estimated, angle_in_pixels(camera_, exact, threshold_));
    }
  }
  return e;
}

std::vector<int> HierarchicalCache::order_nodes(const Vec3& eye, const std::vector<char>& culled) {
  bsp_.back_to_front(eye, order_);
  fragment_position_.assign(bsp_.fragments().size(), 0);
  for (std::size_t i = 0; i < order_.size(); ++i) fragment_position_[order_[i]] = int(i);
  std::vector<int> drawn;  // back to front
  for (std::size_t k = 0; k < nodes_.size(); ++k) {
    bool any = false;
    for (int p : nodes_[k].polygons) any = any || !culled[p];
    if (!any) {
      states_[k]->valid = false;
      continue;
    }
    drawn.push_back(static_cast<int>(k));
  }
  std::sort(drawn.begin(), drawn.end(), [&](int a, int b) {
    return fragment_position_[nodes_[a].fragments[0]] < fragment_position_[nodes_[b].fragments[0]];
  });
  return drawn;
}

bool HierarchicalCache::cacheable(int k, const ViewerPose& current, const Vec3& eye) const {
  // Every box corner beyond the near plane, on the quad's far side and projecting within the
  // guard band.
  const double gw = context_.guard_band * camera_.width;
  const double gh = context_.guard_band * camera_.height;
  bool cacheable = true;
  const CacheQuad quad = cache_quad(eye, nodes_[k].centre());
  for (const Vec3& corner : nodes_[k].corners()) {
    const Vec3 p = to_view(current, corner);
    if (p.z < context_.near || quad_depth(quad, corner) <= 0.0) {
      cacheable = false;
      break;
    }
    const Vec2 q = centred_to_pixel(camera_, project_centred(camera_, p));
    cacheable = cacheable && q.x >= -gw && q.x <= camera_.width + gw && q.y >= -gh &&
                q.y <= camera_.height + gh;
  }
  return cacheable;
}

bool HierarchicalCache::update_node(int k, const ViewerPose& current, const Vec3& eye,
                                    const std::vector<char>& culled, AnimationFrame& report) {
  NodeState& s = *states_[k];
  NodeCacheFrame& c = report.cache;
  FrameReport r;
  r.frame = report.frame;
  r.estimated_error_px = 0.0;  // a render; a reuse estimates per vertex below
  const std::int64_t pixels_before = report.pixels_written;
  const double work_before = report.model_work;
  bool render = !s.valid;
  c.fresh += render;
  if (s.valid) {
    const double angle = node_angular_error(s.quad, nodes_[k].corners(), eye);
    const CacheRenderCause cause =
        cache_render_cause(s.quad, nodes_[k].corners(), s.radius, eye, threshold_);
    c.by_angle += cause == CacheRenderCause::kAngle;
    c.by_sphere += cause == CacheRenderCause::kSphere;
    render = cause != CacheRenderCause::kNone;
    if (!render && !warp_node(k, current, report)) {
      render = true;
      ++c.uncacheable;
    } else if (!render) {
      c.max_angle_deg = std::max(c.max_angle_deg, angle * 180.0 / kPi);
      const VertexErrors e = vertex_errors(k, current);
      r.measured_error_px = e.measured;
      r.estimated_error_px = e.estimated;
    }
  }
  if (render) {
    const bool cached = cacheable(k, current, eye);
    c.uncacheable += !cached;
    render_node(k, current, culled, cached, report);
    ++c.rendered;
  }
  ++c.drawn;
  r.level = render ? Level::kRerender : Level::kPerspective;
  r.pixels_written = report.pixels_written - pixels_before;
  r.model_work = report.model_work - work_before;
  report.max_measured_error_px = std::max(report.max_measured_error_px, r.measured_error_px);
  report.layer_reports.push_back(r);
  return render;
}

double HierarchicalCache::frame(const ViewerPose& current, const std::vector<char>& culled,
                                Image& frame, std::vector<Level>& levels, AnimationFrame& report) {
  const auto t0 = Clock::now();
  NodeCacheFrame& c = report.cache;
  c.active = true;
  c.nodes = static_cast<int>(nodes_.size());
  c.threshold_px = camera_.focal_px * std::tan(threshold_);
  const Vec3 eye = eye_position(current);
  const std::vector<int> drawn = order_nodes(eye, culled);
  std::vector<char> rendered(nodes_.size(), 0);
  for (int k : drawn) {
    if (update_node(k, current, eye, culled, report)) rendered[k] = 1;
  }
  // A polygon is one layer-frame, re-rendered when a node of its was.
  for (std::size_t p = 0; p < scene_.polygons.size(); ++p) {
    if (culled[p]) continue;
    bool any = false;
    for (int k : nodes_of_polygon_[p]) any = any || rendered[k];
    levels[p] = any ? Level::kRerender : Level::kPerspective;
    ++report.levels[static_cast<int>(levels[p])];
  }
  report.update_ms += ms_since(t0);
  const auto t1 = Clock::now();
  frame.fill(Pixel{});
  std::vector<CompositeItem> items;  // the drawn nodes' layers in order, in one pass
  for (int k : drawn) {
    const WarpedLayer& shown = states_[k]->shown;
    items.push_back({&shown.layer, shown.offset_x, shown.offset_y, nullptr});
  }
  report.pixels_composited += composite_all(frame, items);
  report.composite_ms += ms_since(t1);
  const auto t2 = Clock::now();
  measure_pixels(current, drawn, culled, report);
  return ms_since(t2);
}

// Inlined into measure_pixels' rows, which call it for every shown pixel.
inline __attribute__((always_inline)) double HierarchicalCache::pixel_error(
    const NodeState& s, const Mat3& from_frame, const RigidStep3& step, const Vec2& centre) const {
  // Where the cached image's pixel shown here came from, and the surface point there.
  const Vec2 q = apply_homography(from_frame, centre);
  const int qx = static_cast<int>(std::floor(q.x)), qy = static_cast<int>(std::floor(q.y));
  if (qx < 0 || qy < 0 || qx >= s.image.image.width() || qy >= s.image.image.height()) return -1;
  const int plane = s.surface[static_cast<std::size_t>(qy) * s.image.image.width() + qx];
  if (plane < 0) return -1;
  const Vec2 ray = pixel_to_centred(camera_, q + Vec2(s.x0, s.y0)) / camera_.focal_px;
  const Vec3 direction(ray.x, ray.y, 1.0);
  const double inverse_depth = glm::dot(s.planes[plane], direction);
  if (!(inverse_depth > 0.0)) return -1;
  const Vec3 now = step.rotation * (direction / inverse_depth) + step.translation;
  if (now.z < context_.near) return -1;
  return glm::length(centred_to_pixel(camera_, project_centred(camera_, now)) - centre);
}

void HierarchicalCache::measure_pixels(const ViewerPose& current, const std::vector<int>& drawn,
                                       const std::vector<char>& culled, AnimationFrame& report) {
  const int w = camera_.width, h = camera_.height;
  front_node_.assign(static_cast<std::size_t>(w) * h, -1);
  for (int k : drawn) {
    const WarpedLayer& shown = states_[k]->shown;
    label_covered(shown.layer.image, shown.offset_x, shown.offset_y, w, h, k, front_node_);
  }
  NodeCacheFrame& c = report.cache;
  const DepthFrame exact = render_depth(scene_, camera_, current, context_.near);
  std::vector<Mat3> from_frame(nodes_.size(), Mat3(1.0));
  std::vector<RigidStep3> steps(nodes_.size());
  for (int k : drawn) {
    if (!states_[k]->reused) continue;
    from_frame[k] = glm::inverse(states_[k]->to_frame);
    steps[k] = viewer_step(states_[k]->view, current);
  }
  // Rows in bands on the worker threads; each band keeps its tallies (on a cache line of its own)
  // and its errors in raster order, summed band after band: the same sum and order as one pass.
  struct alignas(64) Band {
    std::int64_t overlap = 0, candidates = 0;
    double max_error = 0.0;
    std::vector<double> errors;
  };
  std::array<Band, kMaxBands> bands;
  for_each_band(h, 32, [&](int band, int y0, int y1) {
    Band& b = bands[static_cast<std::size_t>(band)];
    const std::vector<int> none;
    for (int y = y0; y < y1; ++y) {
      for (int x = 0; x < w; ++x) {
        const std::size_t i = static_cast<std::size_t>(y) * w + x;
        const int k = front_node_[i];
        const int p = exact.polygon[i];
        if (k < 0) {
          b.candidates += p >= 0;
          continue;
        }
        const std::vector<int>& of = p >= 0 ? nodes_of_polygon_[p] : none;
        b.overlap += std::find(of.begin(), of.end(), k) == of.end();
        const NodeState& s = *states_[k];
        if (!s.reused) continue;
        const double e = pixel_error(s, from_frame[k], steps[k], Vec2(x + 0.5, y + 0.5));
        if (e < 0.0) continue;
        b.max_error = std::max(b.max_error, e);
        b.errors.push_back(e);
      }
    }
  });
  double sum = 0.0;
  std::int64_t candidates = 0;
  for (const Band& b : bands) {
    c.overlap_pixels += b.overlap;
    candidates += b.candidates;
    c.max_pixel_error_px = std::max(c.max_pixel_error_px, b.max_error);
    for (double e : b.errors) sum += e;
    c.error_pixels += static_cast<std::int64_t>(b.errors.size());
  }
  c.mean_pixel_error_px = c.error_pixels > 0 ? sum / c.error_pixels : 0.0;
  if (candidates > 0) report.hole_pixels += count_holes(current, culled);
}

std::int64_t HierarchicalCache::count_holes(const ViewerPose& current,
                                            const std::vector<char>& culled) {
  // The depth sees a polygon wherever its outline is, but a content may be transparent there
  // (an impostor's facade): a hole is where the exact frame is opaque and no node image is.
  const Image exact = exact_frame(current, culled);
  std::int64_t holes = 0;
  for (int y = 0; y < camera_.height; ++y) {
    for (int x = 0; x < camera_.width; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * camera_.width + x;
      holes += front_node_[i] < 0 && exact.at(x, y).a >= kCoverAlpha;
    }
  }
  return holes;
}

}  // namespace oflab

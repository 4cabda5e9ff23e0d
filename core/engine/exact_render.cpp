// The exact image of a textured plane, whole or clipped (core/engine/exact_render.h).
#include "engine/exact_render.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "engine/cost_model.h"
#include "flow/homography.h"

namespace oflab {
namespace {

// Texel -> top-left pixel homography of the plane's texture rectangle, scaled so that its
// denominator is the depth Z of the texel's point (positive in front of the eye, negative
// behind it), whichever corner lies behind the eye.
Mat3 depth_signed_texture_warp(const Camera& camera, const PlanePose& pose) {
  const PlaneAxes a = plane_axes(pose);
  const Mat3 plane_to_camera(a.right, a.up, pose.point);
  const Mat3 h = translation_matrix(camera.cx, camera.cy) * centred_intrinsics(camera) *
                 plane_to_camera * texel_to_plane(pose);
  double largest = 0.0;
  for (int c = 0; c < 3; ++c) {
    for (int r = 0; r < 3; ++r) largest = std::max(largest, std::abs(entry(h, r, c)));
  }
  return h * (1.0 / largest);
}

// Replaces a layer's valid polygon for the lifetime of the guard, restoring it after.
class PolygonSwap {
 public:
  PolygonSwap(Layer& layer, ConvexPolygon polygon)
      : layer_(layer), saved_(std::move(layer_.polygon)) {
    layer_.polygon = std::move(polygon);
  }
  ~PolygonSwap() { layer_.polygon = std::move(saved_); }
  PolygonSwap(const PolygonSwap&) = delete;
  PolygonSwap& operator=(const PolygonSwap&) = delete;

 private:
  Layer& layer_;
  ConvexPolygon saved_;
};

}  // namespace

std::string plane_visibility_problem(const PlanePose& pose) {
  const PoseProblem p = plane_pose_problem(pose);
  if (!p.field.empty()) return p.message;
  for (const Vec3& c : plane_corners(pose)) {
    if (!(c.z > 1e-6)) return "a plane corner is at or behind the eye";
  }
  const double cosine = glm::dot(glm::normalize(pose.normal), glm::normalize(pose.point));
  if (std::abs(cosine) < 1e-3) return "the plane is seen edge-on";
  return "";
}

Mat3 exact_texture_warp(const Camera& camera, const PlanePose& pose) {
  return translation_matrix(camera.cx, camera.cy) * texture_to_image(camera, pose);
}

PlacedLayer render_exact(const Camera& camera, const Layer& texture, const PlanePose& pose,
                         Sampling sampling, WarpStats* stats) {
  PlanePose sized = pose;
  sized.texture_size = glm::ivec2(texture.image.width(), texture.image.height());
  WarpOptions options;
  options.sampling = sampling;
  WarpedLayer w = warp_layer(texture, exact_texture_warp(camera, sized), options);
  if (stats) *stats = w.stats;
  return {std::move(w.layer), w.offset_x, w.offset_y};
}

PlacedLayer render_clipped(const Camera& camera, Layer& texture, const PlanePose& pose,
                           const ViewPolygon& clipped, Sampling sampling, WarpStats* stats) {
  const glm::ivec2 size(texture.image.width(), texture.image.height());
  PlanePose sized = pose;
  sized.texture_size = size;
  double z_min = clipped.points.at(0).z, z_max = z_min;
  for (const Vec3& p : clipped.points) {
    z_min = std::min(z_min, p.z);
    z_max = std::max(z_max, p.z);
  }
  WarpOptions options;
  options.sampling = sampling;
  // The warp's horizon margin must not cut into the clipped polygon itself.
  options.horizon_epsilon = std::clamp(0.5 * z_min / z_max, 1e-4, kDefaultHorizonEpsilon);
  // Only the clipped part of the texture is drawn (the texture's own polygon is restored).
  const PolygonSwap part(texture, texel_polygon(clipped.uv, size));
  WarpedLayer w = warp_layer(texture, depth_signed_texture_warp(camera, sized), options);
  if (stats) *stats = w.stats;
  return {std::move(w.layer), w.offset_x, w.offset_y};
}

PlacedLayer render_clipped_piece(const Camera& camera, const LayerContent& content, Layer& texture,
                                 const PlanePose& pose, const ConvexPolygon& texels,
                                 const ViewPolygon& clipped, Sampling sampling,
                                 std::int64_t* pixels_written, double* model_work, Image* memory) {
  if (content_is_lit(content)) {
    ContentStats stats;
    PlacedLayer placed =
        render_clipped_content(camera, content, pose, texels, clipped, &stats, memory);
    *pixels_written += stats.pixels_written;
    *model_work += stats.work_units * content_unit_cost(content.kind);
    return placed;
  }
  WarpStats stats;
  PlacedLayer placed = render_clipped(camera, texture, pose, clipped, sampling, &stats);
  *pixels_written += stats.pixels_written;
  *model_work += stats.pixels_written * kPerspectiveWarpCost;
  return placed;
}

PlacedLayer render_clipped_content(const Camera& camera, const LayerContent& content,
                                   const PlanePose& pose, const ConvexPolygon& texels,
                                   const ViewPolygon& clipped, ContentStats* stats, Image* memory) {
  WarpedLayer w;
  if (memory) {
    w.layer.image = std::move(*memory);
    *memory = Image();
  }
  const ContentStats s =
      render_content(content, camera, pose, texels, project_to_pixels(camera, clipped), w);
  if (stats) *stats = s;
  return {std::move(w.layer), w.offset_x, w.offset_y};
}

}  // namespace oflab

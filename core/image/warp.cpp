// Layer warps: the public entry points (warp.h) over warp_plan.h and warp_kernels.h.
#include "image/warp.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "image/warp_kernels.h"
#include "image/warp_plan.h"

namespace oflab {
namespace {

WarpKernel kernel_name(bool affine) {
  return affine ? WarpKernel::kAffine : WarpKernel::kPerspective;
}

// Integer-aligned box around the warped polygon, or an exception if it is too large.
void layer_box(const ConvexPolygon& polygon, int& x0, int& y0, int& width, int& height) {
  const BoundingBox box = polygon.bounds();
  const double left = std::floor(box.x_min);
  const double top = std::floor(box.y_min);
  const double w = std::ceil(box.x_max) - left;
  const double h = std::ceil(box.y_max) - top;
  const double limit = static_cast<double>(kMaxImageDimension);
  if (!(w <= limit && h <= limit && std::abs(left) < 1e9 && std::abs(top) < 1e9)) {
    throw std::invalid_argument(
        "warp_layer: the warped layer would exceed " + std::to_string(kMaxImageDimension) +
        " pixels in width or height (extreme magnification or a layer near the horizon); "
        "warp into a frame with warp_layer_into instead");
  }
  x0 = static_cast<int>(left);
  y0 = static_cast<int>(top);
  width = static_cast<int>(w);
  height = static_cast<int>(h);
}

}  // namespace

const char* sampling_name(Sampling sampling) {
  return sampling == Sampling::kBilinear ? "bilinear" : "nearest";
}

bool parse_sampling(const std::string& text, Sampling* sampling) {
  for (int i = 0; i < kSamplingCount; ++i) {
    if (text != sampling_name(static_cast<Sampling>(i))) continue;
    *sampling = static_cast<Sampling>(i);
    return true;
  }
  return false;
}

std::string sampling_name_list(const std::string& separator) {
  std::string list;
  for (int i = 0; i < kSamplingCount; ++i) {
    list += (i == 0 ? "" : separator) + std::string(sampling_name(static_cast<Sampling>(i)));
  }
  return list;
}

WarpStats warp_layer_into(const Layer& source, const Mat3& source_to_dest, Image& output,
                          int output_origin_x, int output_origin_y, const WarpOptions& options) {
  const PreparedWarp prepared = prepare_warp(source, source_to_dest, options);
  const WarpPlan plan = plan_warp(prepared, options.sampling, output.width(), output.height(),
                                  output_origin_x, output_origin_y);
  WarpStats stats;
  stats.kernel_used = kernel_name(prepared.affine_kernel);
  stats.pixels_written = run_warp_kernel(plan, source.image, output);
  return stats;
}

WarpedLayer warp_layer(const Layer& source, const Mat3& source_to_dest,
                       const WarpOptions& options) {
  const PreparedWarp prepared = prepare_warp(source, source_to_dest, options);
  WarpedLayer result;
  result.stats.kernel_used = kernel_name(prepared.affine_kernel);
  if (prepared.warped_polygon.empty()) return result;

  int x0 = 0, y0 = 0, width = 0, height = 0;
  layer_box(prepared.warped_polygon, x0, y0, width, height);
  Image image(width, height);
  const WarpPlan plan = plan_warp(prepared, options.sampling, width, height, x0, y0);
  result.stats.pixels_written = run_warp_kernel(plan, source.image, image);
  // plan.polygon is the warped polygon in the new layer's pixel coordinates.
  result.layer = make_layer(std::move(image), plan.polygon);
  result.offset_x = x0;
  result.offset_y = y0;
  return result;
}

WarpStats warp_affine_into(const Layer& source, const Mat3& source_to_dest, Image& output,
                           int output_origin_x, int output_origin_y, Sampling sampling) {
  return warp_layer_into(source, source_to_dest, output, output_origin_x, output_origin_y,
                         WarpOptions{sampling, WarpKernel::kAffine, kDefaultHorizonEpsilon});
}

WarpStats warp_perspective_into(const Layer& source, const Mat3& source_to_dest, Image& output,
                                int output_origin_x, int output_origin_y, Sampling sampling) {
  return warp_layer_into(source, source_to_dest, output, output_origin_x, output_origin_y,
                         WarpOptions{sampling, WarpKernel::kPerspective, kDefaultHorizonEpsilon});
}

}  // namespace oflab

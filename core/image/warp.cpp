// Layer warps: the public entry points (warp.h) over warp_plan.h and warp_kernels.h.
#include "image/warp.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <stdexcept>
#include <string>
#include <vector>

#include "flow/named_values.h"
#include "image/mipmap_kernel.h"
#include "image/scan_conversion.h"
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

// Each row's span of `polygon` in an image of the given size (empty rows as {0, 0}), into
// `spans` (its memory reused).
void row_spans(const ConvexPolygon& polygon, int width, int height, std::vector<PixelSpan>& spans) {
  spans.assign(static_cast<std::size_t>(height), PixelSpan{});
  ScanConverter scan(polygon, width, height);
  PixelSpan span;
  while (scan.next(span)) spans[static_cast<std::size_t>(span.y)] = span;
}

// `image` was a layer of old_width x old_height pixels, transparent outside `old_polygon`,
// and has been reshaped (same memory, row after row). Makes transparent the pixels the
// old layer covered that the new spans do not: every other pixel is transparent already
// or written by the next warp. For consecutive frames of an animation the two polygons
// nearly coincide, so this touches few pixels.
void clear_previous(const ConvexPolygon& old_polygon, int old_width, int old_height,
                    const std::vector<PixelSpan>& spans, Image& image) {
  const std::int64_t width = image.width();
  const std::int64_t size = static_cast<std::int64_t>(image.pixel_count());
  Pixel* pixels = image.pixels().data();
  const auto clear = [&](std::int64_t row, std::int64_t from, std::int64_t to) {
    if (from < to) std::fill(pixels + row * width + from, pixels + row * width + to, Pixel{});
  };
  ScanConverter scan(old_polygon, old_width, old_height);
  PixelSpan old;
  while (scan.next(old)) {
    std::int64_t i = static_cast<std::int64_t>(old.y) * old_width + old.x_begin;
    const std::int64_t end =
        std::min(size, static_cast<std::int64_t>(old.y) * old_width + old.x_end);
    while (i < end) {  // the old span's flat range, cut into the new rows
      const std::int64_t row = i / width, from = i % width;
      const std::int64_t to = from + std::min(end - i, width - from);
      const PixelSpan& keep = spans[static_cast<std::size_t>(row)];
      const std::int64_t begin = keep.x_begin < keep.x_end ? keep.x_begin : width;
      clear(row, from, std::min<std::int64_t>(to, begin));
      clear(row, std::max<std::int64_t>(from, keep.x_begin < keep.x_end ? keep.x_end : width), to);
      i += to - from;
    }
  }
}

// Runs the plan's kernel; a mipmap plan samples the options' pyramid of `source`, or one
// built here when the options give none. Adds the pixels sampled to *computed.
std::int64_t run_kernel(const WarpPlan& plan, const Image& source, Image& output,
                        const WarpOptions& options, std::int64_t* computed) {
  if (plan.sampling != Sampling::kMipmap) return run_warp_kernel(plan, source, output, computed);
  if (options.pyramid == nullptr) {
    thread_local MipPyramid pyramid;  // memory kept from warp to warp
    build_mip_pyramid(source, pyramid);
    return run_mipmap_kernel(plan, source, pyramid, output, computed);
  }
  return run_mipmap_kernel(plan, source, *options.pyramid, output, computed);
}

// A given pyramid must be of the source's image: its size is checked before anything is
// written.
void check_pyramid(const Layer& source, const WarpOptions& options) {
  if (options.sampling == Sampling::kMipmap && options.pyramid != nullptr &&
      !options.pyramid->fits(source.image)) {
    throw std::invalid_argument(
        "warp: the mip pyramid was built from a " + std::to_string(options.pyramid->base_width) +
        " x " + std::to_string(options.pyramid->base_height) + " image, the source is " +
        std::to_string(source.image.width()) + " x " + std::to_string(source.image.height()));
  }
}

// Runs the kernel with the options' partial warp (WarpOptions::only), recording the pixels it
// computes when the options ask (WarpOptions::computed_pixels). Adds the pixels sampled to
// stats.pixels_computed; returns the pixels written.
std::int64_t run_partial_or_whole(WarpPlan& plan, const Image& source, Image& output,
                                  const WarpOptions& options, WarpStats& stats) {
  plan.only = options.only;
  if (!options.only || !options.computed_pixels) {
    return run_kernel(plan, source, output, options, &stats.pixels_computed);
  }
  thread_local std::vector<std::vector<ColumnRun>> rows;  // memory kept from warp to warp
  rows.resize(static_cast<std::size_t>(plan.output_height));
  for (std::vector<ColumnRun>& row : rows) row.clear();
  plan.computed = &rows;
  const std::int64_t written = run_kernel(plan, source, output, options, &stats.pixels_computed);
  plan.computed = nullptr;
  options.computed_pixels->add(PixelRows::from_runs(plan.origin_y, rows));
  return written;
}

}  // namespace

// Every sampling with its name, in the order of the enum.
constexpr NamedValue<Sampling> kSamplingNames[] = {{Sampling::kNearest, "nearest"},
                                                   {Sampling::kBilinear, "bilinear"},
                                                   {Sampling::kMipmap, "mipmap"}};
static_assert(std::size(kSamplingNames) == kSamplingCount);

const char* sampling_name(Sampling sampling) {
  return name_of_value(kSamplingNames, sampling, "nearest");
}

bool parse_sampling(const std::string& text, Sampling* sampling) {
  return parse_named_value(kSamplingNames, text, sampling);
}

std::string sampling_name_list(const std::string& separator) {
  return named_value_list(kSamplingNames, separator);
}

WarpStats warp_layer_into(const Layer& source, const Mat3& source_to_dest, Image& output,
                          int output_origin_x, int output_origin_y, const WarpOptions& options) {
  check_pyramid(source, options);
  const PreparedWarp prepared = prepare_warp(source, source_to_dest, options);
  WarpPlan plan = plan_warp(prepared, options.sampling, output.width(), output.height(),
                            output_origin_x, output_origin_y);
  WarpStats stats;
  stats.kernel_used = kernel_name(prepared.affine_kernel);
  stats.pixels_written = run_partial_or_whole(plan, source.image, output, options, stats);
  return stats;
}

WarpedLayer warp_layer(const Layer& source, const Mat3& source_to_dest,
                       const WarpOptions& options) {
  WarpedLayer result;
  warp_layer_reusing(source, source_to_dest, result, options);
  return result;
}

void warp_layer_reusing(const Layer& source, const Mat3& source_to_dest, WarpedLayer& result,
                        const WarpOptions& options) {
  check_pyramid(source, options);
  const PreparedWarp prepared = prepare_warp(source, source_to_dest, options);
  WarpStats stats;
  stats.kernel_used = kernel_name(prepared.affine_kernel);
  if (prepared.warped_polygon.empty()) {
    result.layer.image.reshape(0, 0);
    result.layer.polygon = ConvexPolygon();
    result.offset_x = result.offset_y = 0;
    result.stats = stats;
    return;
  }
  int x0 = 0, y0 = 0, width = 0, height = 0;
  layer_box(prepared.warped_polygon, x0, y0, width, height);
  WarpPlan plan = plan_warp(prepared, options.sampling, width, height, x0, y0);
  // Nothing above throws once the layer is touched, so a refused warp leaves it as it was.
  thread_local std::vector<PixelSpan> spans;  // memory kept from warp to warp
  row_spans(plan.polygon, width, height, spans);
  Image& image = result.layer.image;
  const int old_width = image.width(), old_height = image.height();
  image.reshape(width, height);
  clear_previous(result.layer.polygon, old_width, old_height, spans, image);
  stats.pixels_written = run_partial_or_whole(plan, source.image, image, options, stats);
  // plan.polygon is the warped polygon in the new layer's pixel coordinates.
  result.layer.polygon = std::move(plan.polygon);
  result.offset_x = x0;
  result.offset_y = y0;
  result.stats = stats;
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

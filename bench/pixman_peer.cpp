// pixman peer cases for oflab-bench (see pixman_peer.h).
#include "pixman_peer.h"

#include <benchmark/benchmark.h>
#include <pixman.h>

#include <memory>
#include <string>

namespace oflab::bench {
namespace {

// oflab's Pixel is the bytes r, g, b, a, premultiplied: pixman's a8b8g8r8 on a
// little-endian machine (one 32-bit word with r in the low byte).
constexpr pixman_format_code_t kFormat = PIXMAN_a8b8g8r8;

struct ImageDeleter {
  void operator()(pixman_image_t* image) const { pixman_image_unref(image); }
};
using PixmanImage = std::unique_ptr<pixman_image_t, ImageDeleter>;

// A pixman image over oflab's pixels (no copy); `image` must outlive it.
PixmanImage wrap(const Image& image) {
  auto* bits = reinterpret_cast<uint32_t*>(const_cast<Pixel*>(image.pixels().data()));
  return PixmanImage(pixman_image_create_bits(kFormat, image.width(), image.height(), bits,
                                              image.width() * static_cast<int>(sizeof(Pixel))));
}

// The source image set up for the case: output pixel coordinates -> source coordinates.
void set_up_source(pixman_image_t* source, const WarpCase& c, bool bilinear) {
  const Mat3 inverse = glm::inverse(translation_matrix(-c.origin_x, -c.origin_y) * c.warp);
  pixman_f_transform_t f;
  for (int r = 0; r < 3; ++r) {
    for (int k = 0; k < 3; ++k) f.m[r][k] = entry(inverse, r, k);
  }
  pixman_transform_t t;
  pixman_transform_from_pixman_f_transform(&t, &f);
  pixman_image_set_transform(source, &t);
  pixman_image_set_filter(source, bilinear ? PIXMAN_FILTER_BILINEAR : PIXMAN_FILTER_NEAREST,
                          nullptr, 0);
  pixman_image_set_repeat(source, PIXMAN_REPEAT_NONE);
}

void composite(pixman_image_t* source, pixman_image_t* output, const WarpCase& c) {
  pixman_image_composite32(PIXMAN_OP_OVER, source, nullptr, output, 0, 0, 0, 0, 0, 0,
                           c.output_width, c.output_height);
}

}  // namespace

void register_pixman_cases(const std::vector<WarpCase>& cases, bool bilinear_too, int repetitions) {
  for (const WarpCase& c : cases) {
    for (bool bilinear : {false, true}) {
      if (bilinear && !bilinear_too) continue;
      const std::string name =
          std::string("pixman/") + (bilinear ? "bilinear/" : "nearest/") + c.size + "/" + c.matrix;
      benchmark::RegisterBenchmark(
          name.c_str(),
          [c, bilinear](benchmark::State& state) {
            const PixmanImage source = wrap(c.source.image);
            set_up_source(source.get(), c, bilinear);
            Image result(c.output_width, c.output_height);
            const PixmanImage output = wrap(result);
            for (auto _ : state) {
              composite(source.get(), output.get(), c);
              benchmark::DoNotOptimize(result.pixels().data());
              benchmark::ClobberMemory();
            }
            result.fill(Pixel{});  // one call onto a transparent frame, for the check
            composite(source.get(), output.get(), c);
            set_peer_counters(state, c, result,
                              bilinear ? Sampling::kBilinear : Sampling::kNearest);
          })
          ->Repetitions(repetitions)
          ->ReportAggregatesOnly(true)
          ->Unit(benchmark::kMillisecond);
    }
  }
}

}  // namespace oflab::bench

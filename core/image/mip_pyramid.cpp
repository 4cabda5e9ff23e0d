// The mip pyramid (Williams 83; dissertation section 7.5.5): 2 x 2 box-filtered levels and
// the level of a footprint. See mip_pyramid.h for the definitions.
#include "image/mip_pyramid.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "image/bilinear_blend.h"  // OFLAB_WARP_SSE2 with <emmintrin.h>
#include "image/thread_pool.h"

namespace oflab {
namespace {

// The rounded mean of four channel values.
std::uint8_t mean4(int a, int b, int c, int d) {
  return static_cast<std::uint8_t>((a + b + c + d + 2) >> 2);
}

// Row j of `coarse` as the 2 x 2 box reduction of rows 2j and 2j + 1 of `fine` (`top` and
// `bottom`, the same row past an odd last one); a tap beyond an odd last column is clamped.
void reduce_row(const Pixel* top, const Pixel* bottom, int fine_width, Pixel* out,
                int coarse_width) {
  int i = 0;
#if defined(OFLAB_WARP_SSE2)
  // Two output pixels a step from four input pixels of each row: the channels' sums in 16-bit
  // lanes, each pair's two pixels added, then (sum + 2) >> 2, mean4's bytes.
  const __m128i zero = _mm_setzero_si128(), two = _mm_set1_epi16(2);
  for (; 2 * i + 4 <= fine_width && i + 2 <= coarse_width; i += 2) {
    const __m128i a = _mm_loadu_si128(reinterpret_cast<const __m128i*>(top + 2 * i));
    const __m128i b = _mm_loadu_si128(reinterpret_cast<const __m128i*>(bottom + 2 * i));
    const __m128i low = _mm_add_epi16(_mm_unpacklo_epi8(a, zero), _mm_unpacklo_epi8(b, zero));
    const __m128i high = _mm_add_epi16(_mm_unpackhi_epi8(a, zero), _mm_unpackhi_epi8(b, zero));
    const __m128i sums = _mm_unpacklo_epi64(_mm_add_epi16(low, _mm_srli_si128(low, 8)),
                                            _mm_add_epi16(high, _mm_srli_si128(high, 8)));
    const __m128i means = _mm_srli_epi16(_mm_add_epi16(sums, two), 2);
    _mm_storel_epi64(reinterpret_cast<__m128i*>(out + i), _mm_packus_epi16(means, means));
  }
#endif
  const int last_x = fine_width - 1;
  for (; i < coarse_width; ++i) {
    const int x0 = std::min(2 * i, last_x);
    const int x1 = std::min(2 * i + 1, last_x);
    const Pixel& a = top[x0];
    const Pixel& b = top[x1];
    const Pixel& c = bottom[x0];
    const Pixel& d = bottom[x1];
    out[i] = Pixel{mean4(a.r, b.r, c.r, d.r), mean4(a.g, b.g, c.g, d.g), mean4(a.b, b.b, c.b, d.b),
                   mean4(a.a, b.a, c.a, d.a)};
  }
}

// `bordered` (resized here) as `level` with kMipBorder texels replicated on every side.
void add_border(const Image& level, Image& bordered) {
  const int w = level.width(), h = level.height(), b = kMipBorder;
  bordered.reshape(w + 2 * b, h + 2 * b);
  for (int j = 0; j < h + 2 * b; ++j) {
    const Pixel* in = level.row(std::clamp(j - b, 0, h - 1));
    Pixel* out = bordered.row(j);
    std::fill(out, out + b, in[0]);
    std::copy(in, in + w, out + b);
    std::fill(out + b + w, out + 2 * b + w, in[w - 1]);
  }
}

}  // namespace

void halve_image(const Image& fine, Image& coarse) {
  coarse.reshape((fine.width() + 1) / 2, (fine.height() + 1) / 2);
  const int last_y = fine.height() - 1;
  const auto rows = [&](int, int begin, int end) {
    for (int j = begin; j < end; ++j) {
      reduce_row(fine.row(std::min(2 * j, last_y)), fine.row(std::min(2 * j + 1, last_y)),
                 fine.width(), coarse.row(j), coarse.width());
    }
  };
  // In bands on the worker threads where the level is large enough to pay for them.
  const int min_rows = std::max(8, 65536 / std::max(coarse.width(), 1));
  if (coarse.height() >= 2 * min_rows) {
    for_each_band(coarse.height(), min_rows, rows);
  } else {
    rows(0, 0, coarse.height());
  }
}

int mip_top_level(int width, int height) {
  int top = 0;
  for (int size = std::max(width, height); size > 1; size = (size + 1) / 2) ++top;
  return top;
}

void build_mip_pyramid(const Image& image, MipPyramid& pyramid) {
  pyramid.base_width = image.width();
  pyramid.base_height = image.height();
  const int top = image.empty() ? 0 : mip_top_level(image.width(), image.height());
  pyramid.reduced.resize(static_cast<std::size_t>(top));
  pyramid.bordered.resize(static_cast<std::size_t>(top));
  const Image* fine = &image;
  for (int k = 1; k <= top; ++k) {
    Image& coarse = pyramid.reduced[static_cast<std::size_t>(k - 1)];
    halve_image(*fine, coarse);
    add_border(coarse, pyramid.bordered[static_cast<std::size_t>(k - 1)]);
    fine = &coarse;
  }
}

Image box_reduce(const Image& image, int factor) {
  if (factor < 1 || image.width() % factor != 0 || image.height() % factor != 0) {
    throw std::invalid_argument("box_reduce: the factor " + std::to_string(factor) +
                                " must be >= 1 and divide the image's " +
                                std::to_string(image.width()) + " x " +
                                std::to_string(image.height()) + " pixels");
  }
  Image reduced(image.width() / factor, image.height() / factor);
  const int count = factor * factor;
  std::vector<int> sums(static_cast<std::size_t>(reduced.width()) * 4);
  for (int j = 0; j < reduced.height(); ++j) {
    std::fill(sums.begin(), sums.end(), 0);
    for (int y = j * factor; y < (j + 1) * factor; ++y) {
      const Pixel* row = image.row(y);
      for (int x = 0; x < image.width(); ++x) {
        int* sum = &sums[static_cast<std::size_t>(x / factor) * 4];
        sum[0] += row[x].r, sum[1] += row[x].g, sum[2] += row[x].b, sum[3] += row[x].a;
      }
    }
    Pixel* out = reduced.row(j);
    for (int i = 0; i < reduced.width(); ++i) {
      const int* sum = &sums[static_cast<std::size_t>(i) * 4];
      auto mean = [&](int c) { return static_cast<std::uint8_t>((sum[c] + count / 2) / count); };
      out[i] = Pixel{mean(0), mean(1), mean(2), mean(3)};
    }
  }
  return reduced;
}

double footprint_axis(double j00, double j01, double j10, double j11) {
  // Eigenvalues of J^T J = [[p, q], [q, r]]: (p + r)/2 +- sqrt(((p - r)/2)^2 + q^2).
  const double p = j00 * j00 + j10 * j10;
  const double q = j00 * j01 + j10 * j11;
  const double r = j01 * j01 + j11 * j11;
  const double mean = 0.5 * (p + r);
  const double half_gap = 0.5 * (p - r);
  return std::sqrt(mean + std::sqrt(half_gap * half_gap + q * q));
}

double mip_level(double j00, double j01, double j10, double j11, int top) {
  const double sigma = footprint_axis(j00, j01, j10, j11);
  if (!(sigma > 1.0)) return 0.0;  // magnification, no scaling, or NaN
  return std::min(std::log2(sigma), static_cast<double>(top));
}

}  // namespace oflab

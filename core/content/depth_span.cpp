// One span of a flat face drawn with a depth buffer. See depth_span.h.
#include "content/depth_span.h"

#include <cstring>

#include "image/warp_kernels.h"  // warp_avx2_enabled

#if defined(__x86_64__) && defined(__GNUC__)
#define OFLAB_DEPTH_AVX2 1
#include <immintrin.h>
#endif

namespace oflab {
namespace {

#if defined(OFLAB_DEPTH_AVX2)
// Pixels x .. end - 1 eight at a time, as the loop of draw_depth_span draws each: the same
// 1/Z (c0 + a x + by in double, no fused multiply-add, rounded to float), the same test
// (unordered "not <=", so a NaN passes as it does there), the same count, masked stores.
// Returns the first pixel not done (fewer than eight are left).
__attribute__((target("avx2"))) int depth_octets(const DepthRow& plane, Pixel colour, int x,
                                                 int end, float* z, Pixel* row,
                                                 std::int64_t& written) {
  const __m256d step = _mm256_set1_pd(8.0), a = _mm256_set1_pd(plane.a);
  const __m256d c0 = _mm256_set1_pd(plane.c0), by = _mm256_set1_pd(plane.by);
  __m256d low = _mm256_setr_pd(x, x + 1.0, x + 2.0, x + 3.0);
  __m256d high = _mm256_add_pd(low, _mm256_set1_pd(4.0));
  std::uint32_t word = 0;
  std::memcpy(&word, &colour, sizeof(word));
  const __m256i fill = _mm256_set1_epi32(static_cast<int>(word));
  const __m256i alpha = _mm256_set1_epi32(static_cast<int>(0xff000000u));  // Pixel::a
  for (; x + 8 <= end; x += 8) {
    const __m128 z_low =
        _mm256_cvtpd_ps(_mm256_add_pd(_mm256_add_pd(c0, _mm256_mul_pd(a, low)), by));
    const __m128 z_high =
        _mm256_cvtpd_ps(_mm256_add_pd(_mm256_add_pd(c0, _mm256_mul_pd(a, high)), by));
    low = _mm256_add_pd(low, step);
    high = _mm256_add_pd(high, step);
    const __m256 inv_z = _mm256_insertf128_ps(_mm256_castps128_ps256(z_low), z_high, 1);
    const __m256i nearer =
        _mm256_castps_si256(_mm256_cmp_ps(inv_z, _mm256_loadu_ps(z + x), _CMP_NLE_UQ));
    if (_mm256_testz_si256(nearer, nearer)) continue;
    const __m256i before = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(row + x));
    const __m256i clear =
        _mm256_cmpeq_epi32(_mm256_and_si256(before, alpha), _mm256_setzero_si256());
    written += __builtin_popcount(static_cast<unsigned>(
        _mm256_movemask_ps(_mm256_castsi256_ps(_mm256_and_si256(nearer, clear)))));
    _mm256_maskstore_ps(z + x, nearer, inv_z);
    _mm256_maskstore_epi32(reinterpret_cast<int*>(row + x), nearer, fill);
  }
  return x;
}
#endif

}  // namespace

std::int64_t draw_depth_span(const DepthRow& plane, Pixel colour, int x_begin, int x_end, float* z,
                             Pixel* row, bool wide) {
  std::int64_t written = 0;
  int x = x_begin;
#if defined(OFLAB_DEPTH_AVX2)
  static const bool avx2 = warp_avx2_enabled();  // once, not per span (a call into image/)
  if (wide && avx2) x = depth_octets(plane, colour, x, x_end, z, row, written);
#else
  (void)wide;
#endif
  // Locals, so that the stores into the row do not make the compiler load them again.
  const double a = plane.a, c0 = plane.c0, by = plane.by;
  for (; x < x_end; ++x) {
    const float inv_z = static_cast<float>(c0 + a * x + by);
    if (inv_z <= z[x]) continue;
    z[x] = inv_z;
    written += row[x].a == 0;
    row[x] = colour;
  }
  return written;
}

}  // namespace oflab

// Bilinear blend of 2 x 2 blocks of premultiplied RGBA8 pixels with 16-bit fixed-point
// weights, the inner step of the bilinear warp kernels. Internal to core/image/warp_kernels.cpp.
//
// Accuracy: a weight f is the fraction truncated to a multiple of 2^-16. The SSE2 path
// keeps channels as c * 256 in unsigned 16-bit lanes and weighs them with the high half
// of 16 x 16-bit products, mulhi(c * 256, w) = floor(c * w / 256): each lerp
//     c0 * (65535 - f) / 65536 + c1 * f / 65536
// loses under 1/256 of a level to the floors and at most 255 / 65536 to the total weight
// 65535 / 65536, so the result is within 0.03 of the exact interpolation before rounding
// to the nearest level, i.e. within one level of the reference in
// tests/core/warp_reference.cpp. No shifts are needed before or between the passes,
// which keeps the shuffle and shift ports free (they limited the first version, see
// manual/warping.md). x86-64 uses SSE2 (part of the baseline ISA, so no build flag is
// needed; OFLAB_WARP_SSE2 marks it); other targets use a portable per-channel version.
#pragma once

#include <cstdint>
#include <cstring>

#include "image/image.h"

// The SIMD kernels need SSE2 and 64-bit registers (x86-64). Define OFLAB_WARP_PORTABLE to
// build the portable loops instead (to test them on x86-64).
#if defined(__SSE2__) && defined(__x86_64__) && !defined(OFLAB_WARP_PORTABLE)
#define OFLAB_WARP_SSE2 1
#include <emmintrin.h>
#endif

namespace oflab {

constexpr int kBlendWeightBits = 16;
constexpr std::uint32_t kBlendWeightMask = (1u << kBlendWeightBits) - 1;

#if defined(OFLAB_WARP_SSE2)

namespace blend_detail {

// Two pixels A and B from their blocks: `top` = bytes [A00 B00 A10 B10], `bottom` =
// [A01 B01 A11 B11]. fx, fy hold each pixel's weight as 16-bit lanes [a a a a b b b b].
// Returns A, B as 8 bytes in the low half.
inline __m128i blend_rows(__m128i top, __m128i bottom, __m128i fx, __m128i fy) {
  const __m128i zero = _mm_setzero_si128();
  const __m128i ones = _mm_set1_epi16(-1);
  const __m128i gx = _mm_xor_si128(fx, ones);  // 65535 - fx
  const __m128i gy = _mm_xor_si128(fy, ones);
  // Unpacking below zero bytes gives c * 256 (units of 1/256 level).
  const __m128i t = _mm_add_epi16(_mm_mulhi_epu16(_mm_unpacklo_epi8(zero, top), gx),
                                  _mm_mulhi_epu16(_mm_unpackhi_epi8(zero, top), fx));
  const __m128i b = _mm_add_epi16(_mm_mulhi_epu16(_mm_unpacklo_epi8(zero, bottom), gx),
                                  _mm_mulhi_epu16(_mm_unpackhi_epi8(zero, bottom), fx));
  // t, b <= 255 * 256; the vertical pass keeps the same units, then rounds.
  const __m128i v = _mm_add_epi16(_mm_mulhi_epu16(t, gy), _mm_mulhi_epu16(b, fy));
  const __m128i r = _mm_srli_epi16(_mm_add_epi16(v, _mm_set1_epi16(128)), 8);
  return _mm_packus_epi16(r, r);
}

inline __m128i load_pair(const Pixel* p) {
  return _mm_loadl_epi64(reinterpret_cast<const __m128i*>(p));
}

inline __m128i load_one(const Pixel* p) {
  int word;
  std::memcpy(&word, p, sizeof(word));
  return _mm_cvtsi32_si128(word);
}

// 16-bit lanes [wa wa wa wa wb wb wb wb].
inline __m128i weight_pair(std::uint32_t wa, std::uint32_t wb) {
  const __m128i v = _mm_cvtsi32_si128(static_cast<int>(wa | (wb << 16)));
  const __m128i t = _mm_unpacklo_epi16(v, v);
  return _mm_unpacklo_epi32(t, t);
}

inline Pixel low_pixel(__m128i v) {
  const auto word = static_cast<std::uint32_t>(_mm_cvtsi128_si32(v));
  return Pixel{static_cast<std::uint8_t>(word), static_cast<std::uint8_t>(word >> 8),
               static_cast<std::uint8_t>(word >> 16), static_cast<std::uint8_t>(word >> 24)};
}

}  // namespace blend_detail

// Two output pixels at once from the blocks with top-left pixels a and b (rows `stride`
// pixels apart); fx, fy hold each pixel's weights in [0, 2^16) as 16-bit lanes
// [a a a a b b b b]. Writes out[0] and out[1].
inline void blend_block_pair(const Pixel* a, const Pixel* b, std::int64_t stride, __m128i fx,
                             __m128i fy, Pixel* out) {
  using namespace blend_detail;
  const __m128i top = _mm_unpacklo_epi32(load_pair(a), load_pair(b));
  const __m128i bottom = _mm_unpacklo_epi32(load_pair(a + stride), load_pair(b + stride));
  _mm_storel_epi64(reinterpret_cast<__m128i*>(out), blend_rows(top, bottom, fx, fy));
}

// The same with scalar weights (fxa, fya) and (fxb, fyb).
inline void blend_block_pair(const Pixel* a, const Pixel* b, std::int64_t stride, std::uint32_t fxa,
                             std::uint32_t fya, std::uint32_t fxb, std::uint32_t fyb, Pixel* out) {
  using namespace blend_detail;
  blend_block_pair(a, b, stride, weight_pair(fxa, fxb), weight_pair(fya, fyb), out);
}

// One output pixel from four separately addressed taps (clamped at the source border).
inline Pixel blend_taps(const Pixel* p00, const Pixel* p10, const Pixel* p01, const Pixel* p11,
                        std::uint32_t fx, std::uint32_t fy) {
  using namespace blend_detail;
  const __m128i top = _mm_unpacklo_epi64(_mm_unpacklo_epi32(load_one(p00), load_one(p00)),
                                         _mm_unpacklo_epi32(load_one(p10), load_one(p10)));
  const __m128i bottom = _mm_unpacklo_epi64(_mm_unpacklo_epi32(load_one(p01), load_one(p01)),
                                            _mm_unpacklo_epi32(load_one(p11), load_one(p11)));
  return low_pixel(blend_rows(top, bottom, weight_pair(fx, fx), weight_pair(fy, fy)));
}

// One output pixel from the block whose top-left pixel is p.
inline Pixel blend_block(const Pixel* p, std::int64_t stride, std::uint32_t fx, std::uint32_t fy) {
  return blend_taps(p, p + 1, p + stride, p + stride + 1, fx, fy);
}

#else  // portable version: exact per-channel interpolation, rounded

inline Pixel blend_taps(const Pixel* p00, const Pixel* p10, const Pixel* p01, const Pixel* p11,
                        std::uint32_t fx, std::uint32_t fy) {
  const std::uint64_t gx = (1u << kBlendWeightBits) - fx;
  const std::uint64_t gy = (1u << kBlendWeightBits) - fy;
  auto channel = [&](std::uint8_t Pixel::*c) {
    const std::uint64_t v = (p00->*c * gx + p10->*c * fx) * gy + (p01->*c * gx + p11->*c * fx) * fy;
    return static_cast<std::uint8_t>((v + (std::uint64_t{1} << 31)) >> 32);
  };
  return Pixel{channel(&Pixel::r), channel(&Pixel::g), channel(&Pixel::b), channel(&Pixel::a)};
}

inline Pixel blend_block(const Pixel* p, std::int64_t stride, std::uint32_t fx, std::uint32_t fy) {
  return blend_taps(p, p + 1, p + stride, p + stride + 1, fx, fy);
}

inline void blend_block_pair(const Pixel* a, const Pixel* b, std::int64_t stride, std::uint32_t fxa,
                             std::uint32_t fya, std::uint32_t fxb, std::uint32_t fyb, Pixel* out) {
  out[0] = blend_block(a, stride, fxa, fya);
  out[1] = blend_block(b, stride, fxb, fyb);
}

#endif

}  // namespace oflab

// Small exact integer operations on 8-bit channels, shared by the alpha conversions and
// the "over" compositing.
#pragma once

#include <cstdint>

namespace oflab {

// round(v / 255) for 0 <= v <= 255 * 255, halves rounding up, without a division
// (Blinn's formula; exact over that whole range, checked exhaustively in image_test).
inline std::uint8_t div255_round(unsigned v) {
  const unsigned t = v + 128u;
  return static_cast<std::uint8_t>((t + (t >> 8)) >> 8);
}

}  // namespace oflab

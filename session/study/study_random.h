// The study's own random numbers: SplitMix64 (Steele, Lea and Flood 2014) to seed, and
// xoshiro256** (Blackman and Vigna 2018) to draw. Every number the experiment draws (the
// order of conditions, which interval holds the distorted clip, a simulated observer's
// answers, bootstrap resamples) comes from here, never from <random>'s distributions, whose
// output differs between standard libraries: one seed gives the same trial sequence in the
// desktop window, on the page (emscripten) and in `oflab-cli study`. Plain C++.
#pragma once

#include <cstdint>

namespace oflab {

// SplitMix64: a 64-bit counter through a mixing function; used to spread one seed over the
// four words of xoshiro's state (as its authors recommend).
class SplitMix64 {
 public:
  explicit SplitMix64(std::uint64_t seed) : state_(seed) {}
  // The next 64-bit output.
  std::uint64_t next();

 private:
  std::uint64_t state_;
};

// xoshiro256**: 256 bits of state, period 2^256 - 1.
class StudyRandom {
 public:
  // The state from SplitMix64(seed)'s first four outputs (never all zero).
  explicit StudyRandom(std::uint64_t seed);
  // The state given word by word (the reference implementation's s[0..3]); not all zero.
  StudyRandom(std::uint64_t s0, std::uint64_t s1, std::uint64_t s2, std::uint64_t s3);

  // The next 64-bit output.
  std::uint64_t next();
  // A uniform number in [0, 1): the top 53 bits of next() times 2^-53 (exact in a double).
  double uniform();
  // A whole number in [0, n), n >= 1, without modulo bias (outputs below 2^64 mod n are
  // drawn again).
  std::uint64_t below(std::uint64_t n);
  // True with probability p (p clamped to [0, 1]): uniform() < p.
  bool chance(double p) { return uniform() < p; }

 private:
  std::uint64_t s_[4];
};

}  // namespace oflab

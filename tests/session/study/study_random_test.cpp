// The study's random numbers (session/study/study_random.h) against the published reference
// outputs of SplitMix64 and xoshiro256**, and the properties the experiment relies on.
#include "study/study_random.h"

#include <gtest/gtest.h>

#include <vector>

namespace oflab {
namespace {

// SplitMix64 seeded with 1234567: the reference sequence of the algorithm as published
// (Rosetta Code's "Pseudo-random numbers/Splitmix64", from Vigna's splitmix64.c).
TEST(StudyRandom, SplitMix64MatchesItsReferenceSequence) {
  SplitMix64 g(1234567);
  const std::vector<std::uint64_t> expected = {6457827717110365317ULL, 3203168211198807973ULL,
                                               9817491932198370423ULL, 4593380528125082431ULL,
                                               16408922859458223821ULL};
  for (std::uint64_t e : expected) EXPECT_EQ(g.next(), e);
}

// xoshiro256** with the state {1, 2, 3, 4}: the first ten outputs of the reference
// implementation xoshiro256starstar.c (as its ports test them).
TEST(StudyRandom, Xoshiro256StarStarMatchesItsReferenceSequence) {
  StudyRandom g(1, 2, 3, 4);
  const std::vector<std::uint64_t> expected = {11520ULL,
                                               0ULL,
                                               1509978240ULL,
                                               1215971899390074240ULL,
                                               1216172134540287360ULL,
                                               607988272756665600ULL,
                                               16172922978634559625ULL,
                                               8476171486693032832ULL,
                                               10595114339597558777ULL,
                                               2904607092377533576ULL};
  for (std::uint64_t e : expected) EXPECT_EQ(g.next(), e);
}

TEST(StudyRandom, OneSeedGivesOneSequenceAndAnotherSeedAnother) {
  StudyRandom a(43), b(43), c(44);
  int same = 0;
  for (int i = 0; i < 100; ++i) {
    const std::uint64_t x = a.next();
    EXPECT_EQ(x, b.next());
    same += x == c.next();
  }
  EXPECT_EQ(same, 0);
}

TEST(StudyRandom, UniformNumbersFillTheUnitIntervalEvenly) {
  StudyRandom g(5);
  std::vector<int> bins(10, 0);
  constexpr int kDraws = 100000;
  for (int i = 0; i < kDraws; ++i) {
    const double u = g.uniform();
    ASSERT_GE(u, 0.0);
    ASSERT_LT(u, 1.0);
    ++bins[size_t(u * 10)];
  }
  // Each bin expects 10 000 with a standard deviation of 95: 5 sigma is 475.
  for (int n : bins) EXPECT_NEAR(n, kDraws / 10, 475);
}

TEST(StudyRandom, BelowStaysInRangeAndReachesEveryValue) {
  StudyRandom g(9);
  std::vector<int> counts(7, 0);
  for (int i = 0; i < 70000; ++i) {
    const std::uint64_t k = g.below(7);
    ASSERT_LT(k, 7u);
    ++counts[size_t(k)];
  }
  for (int n : counts) EXPECT_NEAR(n, 10000, 450);  // sigma 93
  EXPECT_EQ(g.below(1), 0u);
}

}  // namespace
}  // namespace oflab

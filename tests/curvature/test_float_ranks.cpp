// FloatRanks (the colour range's percentiles) against a full sort: random
// values with many repeats, both zeros, values of one bucket only, a mask
// that leaves some out, and the smallest sets.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "libcore/curvature/float_ranks.h"

namespace isoform {
namespace {

// Every rank of the kept values, compared as floats (so -0 and +0 are equal,
// as they are to the colour range).
void expect_all_ranks(const std::vector<float>& values, const std::vector<uint8_t>& keep) {
  std::vector<float> sorted;
  for (size_t i = 0; i < values.size(); ++i)
    if (keep[i]) sorted.push_back(values[i]);
  std::sort(sorted.begin(), sorted.end());
  const auto ranks = float_ranks(values.data(), values.size(), [&](size_t i) { return keep[i] != 0; });
  ASSERT_EQ(ranks.count(), sorted.size());
  for (size_t r = 0; r < sorted.size(); r += 1 + sorted.size() / 97) {
    const size_t s = sorted.size() - 1 - r;
    float a = NAN, b = NAN;
    ranks.at(r, s, &a, &b);
    EXPECT_EQ(a, sorted[r]) << "rank " << r;
    EXPECT_EQ(b, sorted[s]) << "rank " << s;
  }
}

TEST(FloatRanks, KeysKeepTheOrderOfTheFloats) {
  const float xs[] = {-std::numeric_limits<float>::infinity(), -3e38f, -1.5f, -1e-40f, -0.0f, 0.0f,
                      1e-40f, 1e-7f, 1.0f, 1.0000001f, 3e38f, std::numeric_limits<float>::infinity()};
  for (size_t i = 0; i + 1 < sizeof xs / sizeof xs[0]; ++i) {
    EXPECT_LT(float_key(xs[i]), float_key(xs[i + 1])) << xs[i] << " " << xs[i + 1];
    EXPECT_EQ(std::signbit(key_float(float_key(xs[i]))), std::signbit(xs[i]));
    EXPECT_EQ(key_float(float_key(xs[i])), xs[i]);
  }
}

TEST(FloatRanks, EveryRankIsTheSortedValue) {
  std::mt19937 rng(5);
  std::normal_distribution<float> wide(0.2f, 3.0f);
  std::uniform_int_distribution<int> few(-20, 20), coin(0, 9);
  for (int kind = 0; kind < 4; ++kind) {
    std::vector<float> v(20000);
    std::vector<uint8_t> keep(v.size(), 1);
    for (size_t i = 0; i < v.size(); ++i) {
      switch (kind) {
        case 0: v[i] = wide(rng); break;                          // spread over many buckets
        case 1: v[i] = 0.01f * float(few(rng)); break;            // a few values, many repeats, both zeros
        case 2: v[i] = 1.0f + 1e-6f * float(few(rng)); break;     // all in one or two buckets
        case 3: v[i] = coin(rng) < 5 ? -0.0f : 0.0f; break;       // zeros only
      }
      if (kind == 1 && coin(rng) == 0) v[i] = -0.0f;
      keep[i] = coin(rng) != 0;  // a tenth left out
    }
    expect_all_ranks(v, keep);
  }
}

TEST(FloatRanks, SmallSetsAndLeftOutValues) {
  expect_all_ranks({2.5f}, {1});
  expect_all_ranks({-1.0f, 7.0f}, {1, 1});
  expect_all_ranks({9.0f, -4.0f, 1e30f, 3.0f}, {0, 1, 0, 1});  // the left-out extremes do not count
  const std::vector<float> none = {1.0f, 2.0f};
  EXPECT_EQ(float_ranks(none.data(), none.size(), [](size_t) { return false; }).count(), 0u);
}

}  // namespace
}  // namespace isoform

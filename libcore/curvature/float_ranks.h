// Order statistics of a set of floats without copying or sorting them.
//
// Each float has an order-preserving 32-bit key (its bits with the sign bit
// set for positives, all bits flipped for negatives; -0 then comes just
// before +0, which compare equal as floats). A histogram of the keys' top
// 16 bits, made in one pass, finds the bucket that holds a rank; a second
// pass collects the low 16 bits of that bucket's values, and a selection
// among those alone gives the exact value. Two passes over the values
// whatever their distribution, where a selection over all of them
// (std::nth_element) moves every value several times.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <vector>

namespace isoform {

inline uint32_t float_key(float x) {
  uint32_t b;
  std::memcpy(&b, &x, sizeof b);
  return b ^ (uint32_t(int32_t(b) >> 31) | 0x80000000u);  // without a branch: signs come mixed
}

inline float key_float(uint32_t key) {
  const uint32_t b = (key & 0x80000000u) ? (key & 0x7fffffffu) : ~key;
  float x;
  std::memcpy(&x, &b, sizeof x);
  return x;
}

// The values are values[i] for each i < n with keep(i) true, none NaN.
template <class Keep>
class FloatRanks {
 public:
  FloatRanks(const float* values, size_t n, Keep keep)
      : values_(values), n_(n), keep_(keep), histogram_(size_t(1) << 16, 0) {
    for (size_t i = 0; i < n; ++i)
      if (keep_(i)) {
        ++histogram_[float_key(values[i]) >> 16];
        ++count_;
      }
  }
  size_t count() const { return count_; }

  // The r1-th and r2-th smallest values (0: the smallest), both < count(),
  // from one more pass.
  void at(size_t r1, size_t r2, float* v1, float* v2) const {
    const size_t rank[2] = {r1, r2};
    uint32_t bucket[2];
    size_t below[2];
    for (int k = 0; k < 2; ++k) {
      bucket[k] = 0;
      below[k] = 0;
      while (below[k] + histogram_[bucket[k]] <= rank[k]) below[k] += histogram_[bucket[k]++];
    }
    std::vector<uint16_t> low[2];
    for (int k = 0; k < 2; ++k) low[k].reserve(histogram_[bucket[k]]);
    for (size_t i = 0; i < n_; ++i)
      if (keep_(i)) {
        const uint32_t key = float_key(values_[i]), top = key >> 16;
        if (top == bucket[0]) low[0].push_back(uint16_t(key));
        if (top == bucket[1] && bucket[1] != bucket[0]) low[1].push_back(uint16_t(key));
      }
    float* out[2] = {v1, v2};
    for (int k = 0; k < 2; ++k) {
      std::vector<uint16_t>& in = bucket[k] == bucket[0] ? low[0] : low[1];
      const auto nth = in.begin() + long(rank[k] - below[k]);
      std::nth_element(in.begin(), nth, in.end());
      *out[k] = key_float(bucket[k] << 16 | *nth);
    }
  }

 private:
  const float* values_;
  size_t n_;
  Keep keep_;
  std::vector<uint32_t> histogram_;  // values per top 16 key bits
  size_t count_ = 0;
};

template <class Keep>
FloatRanks<Keep> float_ranks(const float* values, size_t n, Keep keep) {
  return FloatRanks<Keep>(values, n, keep);
}

}  // namespace isoform

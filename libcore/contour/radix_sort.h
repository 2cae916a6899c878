// A stable least-significant-digit radix sort for the merge's two large
// sorts (shared-vertex keys, seam edges): 8 bits per pass over the key's
// low bits, each pass counting and scattering fixed chunks in parallel.
// Being stable, it leaves records with equal keys in their input order, so
// records sorted by (key, position) come out as a comparison sort on that
// pair would put them; the chunks do not depend on the number of threads.
#pragma once

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace isoform {

// Sorts data[0, n) stably by the bits low_bit .. bits - 1 of key(record), a
// uint64_t below 2^bits, using buffer (room for n records, contents
// ignored) as scratch. The result is in data. Passes whose digit is the
// same in every record are skipped. Runs in parallel with TBB in the calling
// task arena.
template <class T, class Key>
void radix_sort(T* data, T* buffer, size_t n, int bits, const Key& key, int low_bit = 0) {
  constexpr int kDigitBits = 8;
  constexpr size_t kBuckets = size_t(1) << kDigitBits;
  if (n < 2) return;
  const size_t chunks = std::clamp<size_t>(n >> 15, 1, 64);
  const size_t per = (n + chunks - 1) / chunks;
  std::vector<size_t> count(chunks * kBuckets);
  T* from = data;
  T* to = buffer;
  for (int shift = low_bit; shift < bits; shift += kDigitBits) {
    tbb::parallel_for(size_t(0), chunks, [&](size_t c) {
      size_t* h = &count[c * kBuckets];
      std::fill(h, h + kBuckets, size_t(0));
      const size_t end = std::min(n, (c + 1) * per);
      for (size_t i = c * per; i < end; ++i) ++h[(key(from[i]) >> shift) & (kBuckets - 1)];
    });
    // Each chunk's first place per digit: digit by digit, chunk by chunk.
    size_t sum = 0;
    bool one_digit = false;
    for (size_t d = 0; d < kBuckets; ++d) {
      const size_t before = sum;
      for (size_t c = 0; c < chunks; ++c) {
        size_t& at = count[c * kBuckets + d];
        const size_t m = at;
        at = sum;
        sum += m;
      }
      one_digit |= sum - before == n;
    }
    if (one_digit) continue;
    tbb::parallel_for(size_t(0), chunks, [&](size_t c) {
      size_t* at = &count[c * kBuckets];
      const size_t end = std::min(n, (c + 1) * per);
      for (size_t i = c * per; i < end; ++i) to[at[(key(from[i]) >> shift) & (kBuckets - 1)]++] = from[i];
    });
    std::swap(from, to);
  }
  if (from != data) {
    tbb::parallel_for(size_t(0), chunks, [&](size_t c) {
      const size_t begin = c * per, end = std::min(n, (c + 1) * per);
      if (begin < end) std::copy(from + begin, from + end, data + begin);
    });
  }
}

// Bits needed for the values 0 .. v.
inline int radix_bits_for(uint64_t v) { return v == 0 ? 0 : 64 - __builtin_clzll(v); }

}  // namespace isoform

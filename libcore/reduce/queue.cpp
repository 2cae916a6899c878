// The passes' queue (see queue.h).
#include "queue.h"

#include <algorithm>
#include <cstring>
#include <tuple>

#include <tbb/parallel_for.h>

#include "weights.h"

namespace isoform::reduce {
namespace {

// A function object rather than a function, so that the sorts and the
// merge inline the comparison.
struct Lighter {
  bool operator()(const QueueEntry& a, const QueueEntry& b) const {
    return std::tie(a.weight, a.face) < std::tie(b.weight, b.face);
  }
};
constexpr Lighter lighter{};

// Sets w.weight of face f from its vertices (5.21-5.23).
void update_weight(WorkMesh& w, int f) {
  const auto& t = w.tri[size_t(f)];
  const double sigma = angle_weight(w.pos[size_t(t[0])], w.pos[size_t(t[1])], w.pos[size_t(t[2])]);
  w.weight[size_t(f)] = triangle_weight(sigma, w.absolute[size_t(t[0])], w.absolute[size_t(t[1])],
                                        w.absolute[size_t(t[2])]);
}

// The key of a weight whose unsigned order is the order of the weights
// (negative ones too; -0 as +0, so equal weights have equal keys).
uint64_t weight_key(double weight) {
  if (weight == 0) weight = 0;
  uint64_t bits;
  std::memcpy(&bits, &weight, sizeof bits);
  return bits >> 63 ? ~bits : bits | (uint64_t(1) << 63);
}

// Sorts entries given in increasing face order lightest first, ties by face:
// a stable least-significant-digit radix sort of the weights' keys, 11 bits
// a step, each step left out where every key has the same digit.
// NOTE: O(n) in a few sweeps, against the comparison sort's log n: a pass's
// first order holds every face, and sorting it by comparisons was a share
// of a whole reduction's time worth saving.
void sort_lightest_first(std::vector<QueueEntry>& v, std::vector<QueueEntry>& scratch) {
  if (v.size() < 2048) {
    std::sort(v.begin(), v.end(), lighter);
    return;
  }
  constexpr int kBits = 11, kDigits = 1 << kBits, kSteps = (64 + kBits - 1) / kBits;
  std::vector<uint32_t> count(size_t(kSteps) * kDigits, 0);
  for (const QueueEntry& e : v) {
    const uint64_t key = weight_key(e.weight);
    for (int s = 0; s < kSteps; ++s) ++count[size_t(s) * kDigits + ((key >> (s * kBits)) & (kDigits - 1))];
  }
  scratch.resize(v.size());
  for (int s = 0; s < kSteps; ++s) {
    uint32_t* c = &count[size_t(s) * kDigits];
    const uint64_t first = (weight_key(v.front().weight) >> (s * kBits)) & (kDigits - 1);
    if (c[first] == v.size()) continue;  // one digit for all
    uint32_t at = 0;
    for (int d = 0; d < kDigits; ++d) {
      const uint32_t n = c[d];
      c[d] = at;
      at += n;
    }
    for (const QueueEntry& e : v) scratch[c[(weight_key(e.weight) >> (s * kBits)) & (kDigits - 1)]++] = e;
    v.swap(scratch);
  }
}

}  // namespace

void compute_weights(WorkMesh& w) {
  w.weight.assign(w.tri.size(), 0.0);
  tbb::parallel_for(size_t(0), w.tri.size(), [&](size_t f) { update_weight(w, int(f)); });
}

const std::vector<QueueEntry>& PassQueue::next_pass(const WorkMesh& w, int pass) {
  if (pass == 1) {
    order_.clear();
    for (size_t f = 0; f < w.tri.size(); ++f)
      if (w.face_alive[f]) order_.push_back({w.weight[f], int(f), w.face_stamp[f]});
    sort_lightest_first(order_, merged_);
    return order_;
  }
  // The faces of the last pass's removals that are still there, sorted; and
  // one bit per face: alive and not made in the last pass.
  // NOTE: the bits are set in parallel, 64 faces a word; the new faces are
  // then read off their bits in id order, as the serial loop took them.
  const size_t words = (w.tri.size() + 63) / 64;
  old_.assign(words, 0);
  made_.assign(words, 0);
  tbb::parallel_for(size_t(0), words, [&](size_t k) {
    for (size_t f = 64 * k; f < std::min(w.tri.size(), 64 * k + 64); ++f) {
      if (!w.face_alive[f]) continue;
      uint64_t& word = w.face_pass[f] == pass - 1 ? made_[k] : old_[k];
      word |= uint64_t(1) << (f % 64);
    }
  });
  fresh_.clear();
  for (size_t k = 0; k < words; ++k)
    for (uint64_t bits = made_[k]; bits != 0; bits &= bits - 1) {
      const size_t f = 64 * k + size_t(__builtin_ctzll(bits));
      fresh_.push_back({w.weight[f], int(f), w.face_stamp[f]});
    }
  sort_lightest_first(fresh_, merged_);
  // The older faces keep their order; the changed and removed ones drop out.
  // NOTE: every entry here was current when the last pass began, and a face
  // that changes during a pass either goes or is made anew in that pass
  // (Remover::commit), so an entry is still current exactly when its face
  // is alive and was not made in the last pass: the bits above, read in a
  // small array, instead of each entry's face and stamp all over memory.
  order_.erase(std::remove_if(order_.begin(), order_.end(),
                              [&](const QueueEntry& e) {
                                const size_t f = size_t(e.face);
                                return !(old_[f / 64] >> (f % 64) & 1);
                              }),
               order_.end());
  merged_.resize(order_.size() + fresh_.size());
  std::merge(order_.begin(), order_.end(), fresh_.begin(), fresh_.end(), merged_.begin(), lighter);
  order_.swap(merged_);
  return order_;
}

}  // namespace isoform::reduce

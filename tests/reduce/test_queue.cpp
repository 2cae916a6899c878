// The passes' queue (libcore/reduce/queue.h): every pass's order is the
// order a full sort of the live faces by (weight, face id) gives, with the
// radix sort on many faces and many equal weights, and after a pass's
// removals and new faces.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <tuple>
#include <vector>

#include "libcore/reduce/queue.h"

namespace isoform::reduce {
namespace {

std::vector<int> sorted_live_faces(const WorkMesh& w) {
  std::vector<int> faces;
  for (size_t f = 0; f < w.tri.size(); ++f)
    if (w.face_alive[f]) faces.push_back(int(f));
  std::sort(faces.begin(), faces.end(),
            [&](int a, int b) { return std::tie(w.weight[size_t(a)], a) < std::tie(w.weight[size_t(b)], b); });
  return faces;
}

std::vector<int> faces_of(const std::vector<QueueEntry>& order) {
  std::vector<int> faces;
  for (const QueueEntry& e : order) faces.push_back(e.face);
  return faces;
}

// Weights as the reduction makes them, and harder: many ties (a plane's
// faces all weigh the same), zeros of both signs, tiny and huge values,
// values apart only in their last bits.
double random_weight(std::mt19937& rng) {
  switch (std::uniform_int_distribution<int>(0, 6)(rng)) {
    case 6: return 1.0 + std::uniform_int_distribution<int>(0, 4095)(rng) * 0x1p-52;  // apart in the last bits
    case 0: return 0.25;
    case 1: return 0.0;
    case 2: return -0.0;
    case 3: return std::ldexp(std::uniform_real_distribution<double>(1, 2)(rng), -900);
    case 4: return std::ldexp(std::uniform_real_distribution<double>(1, 2)(rng), 500);
    default: return std::uniform_real_distribution<double>(0, 3)(rng);
  }
}

TEST(PassQueue, EveryPassIsTheFullSortsOrder) {
  std::mt19937 rng(7);
  for (size_t n : {size_t(100), size_t(50000)}) {  // the comparison sort, and the radix sort
    WorkMesh w;
    w.tri.assign(n, {0, 1, 2});
    w.face_alive.assign(n, 1);
    w.face_stamp.assign(n, 0);
    w.face_pass.assign(n, 0);
    w.weight.resize(n);
    for (double& x : w.weight) x = random_weight(rng);
    PassQueue queue;
    EXPECT_EQ(faces_of(queue.next_pass(w, 1)), sorted_live_faces(w)) << n << " faces, pass 1";
    // Pass 1 removes a third of the faces and remakes a sixth with new
    // weights (as Remover::commit does: a new stamp and the pass).
    for (size_t f = 0; f < n; ++f) {
      const int r = std::uniform_int_distribution<int>(0, 5)(rng);
      if (r < 2) {
        w.face_alive[f] = 0;
        ++w.face_stamp[f];
      } else if (r == 2) {
        w.weight[f] = random_weight(rng);
        w.face_pass[f] = 1;
        ++w.face_stamp[f];
      }
    }
    const std::vector<QueueEntry>& order = queue.next_pass(w, 2);
    EXPECT_EQ(faces_of(order), sorted_live_faces(w)) << n << " faces, pass 2";
    for (const QueueEntry& e : order) {
      ASSERT_EQ(e.stamp, w.face_stamp[size_t(e.face)]);
      ASSERT_EQ(e.weight, w.weight[size_t(e.face)]);
    }
  }
}

}  // namespace
}  // namespace isoform::reduce

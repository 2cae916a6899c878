// The tracker's lists (tracker.h, relink). Without a tolerance a new face
// keeps at most kSample of the original vertices handed to it, the same ones
// in whatever order they come; with a distance tolerance it keeps them all.
#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <numeric>
#include <random>

#include "libcore/reduce/tracker.h"

namespace isoform::reduce {
namespace {

// n vertices, each the one corner of a face of its own (vertex v, face v):
// the tracker lists vertex v under face v.
WorkMesh singles(int n) {
  WorkMesh w;
  w.vfaces.reset(size_t(n));
  for (int v = 0; v < n; ++v) {
    w.pos.push_back(Eigen::Vector3d(v, 0, 0));
    w.tri.push_back({v, v, v});
    w.face_alive.push_back(1);
    w.vfaces.push_back(size_t(v), v);
  }
  w.live_faces = n;
  return w;
}

// A removal of every face whose n vertices go to three new faces (ids 0, 1,
// 2): vertex v to the new face `to[v]`, handed over in the order `order`.
void relink_all(Tracker& tracker, int n, const std::vector<int>& to, const std::vector<int>& order) {
  Platelet p;
  p.faces.resize(size_t(n));
  std::iota(p.faces.begin(), p.faces.end(), 0);
  TrackerPending t;
  for (int v : order) {
    t.vertex.push_back(v);
    t.face.push_back(to[size_t(v)]);
  }
  tracker.relink(p, t, p.faces.data());
}

std::vector<int> sorted(std::vector<int> v) {
  std::sort(v.begin(), v.end());
  return v;
}

TEST(Tracker, WithoutAToleranceANewFaceKeepsASampleWhateverTheOrder) {
  const int n = 60;
  const WorkMesh w = singles(n);
  // 40 vertices to face 0, 17 to face 1, 3 to face 2.
  std::vector<int> to(size_t(n), 0);
  for (int v = 0; v < n; ++v) to[size_t(v)] = v < 40 ? 0 : v < 57 ? 1 : 2;
  std::vector<int> order(size_t(n), 0);
  std::iota(order.begin(), order.end(), 0);
  const double inf = std::numeric_limits<double>::infinity();
  for (bool measure : {false, true}) {
    Tracker first(w, inf, 0.0, measure);
    for (int v = 0; v < n; ++v) ASSERT_EQ(first.listed(v), std::vector<int>{v});
    relink_all(first, n, to, order);
    const size_t handed[3] = {40, 17, 3};
    for (int f = 0; f < 3; ++f) {
      const std::vector<int> kept = first.listed(f);
      EXPECT_EQ(kept.size(), std::min(handed[f], size_t(Tracker::kSample))) << "face " << f;
      for (int v : kept) EXPECT_EQ(to[size_t(v)], f) << "vertex " << v << " under face " << f;
    }
    EXPECT_EQ(sorted(first.listed(2)), (std::vector<int>{57, 58, 59}));
    for (int f = 3; f < n; ++f) EXPECT_TRUE(first.listed(f).empty()) << "face " << f;
    // The same vertices kept when they come in other orders.
    std::mt19937 rng(5);
    for (int round = 0; round < 5; ++round) {
      std::shuffle(order.begin(), order.end(), rng);
      Tracker again(w, inf, 0.0, measure);
      relink_all(again, n, to, order);
      for (int f = 0; f < 3; ++f) EXPECT_EQ(sorted(again.listed(f)), sorted(first.listed(f))) << "face " << f;
    }
  }
  // A distance tolerance bounds every original vertex: all stay listed.
  Tracker bounded(w, 0.5, 0.0, false);
  std::iota(order.begin(), order.end(), 0);
  relink_all(bounded, n, to, order);
  EXPECT_EQ(bounded.listed(0).size(), 40u);
  EXPECT_EQ(bounded.listed(1).size(), 17u);
  EXPECT_EQ(bounded.listed(2).size(), 3u);
}

}  // namespace
}  // namespace isoform::reduce

// The self-overlap check of the reduction's input: the triangle pair test on
// hand-made cases (crossing, contact, coplanar, shared vertex, shared edge,
// fold), and the grid's pairs against all pairs on meshes that do and do not
// overlap themselves, flat and tilted, and with triangles far larger than
// the rest among them.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <set>
#include <utility>

#include "libcore/errors.h"
#include "libcore/reduce/mesh_overlap.h"
#include "libcore/reduce/triangle_overlap.h"
#include "libcore/reduce/validate.h"
#include "test_meshes.h"

namespace isoform::reduce {
namespace {

struct Tri {
  Point3 p[3];
  int32_t v[3];
};

PairOverlap test(const Tri& a, const Tri& b) { return triangles_overlap(a.p, a.v, b.p, b.v); }

// The unit right triangle in z = 0, vertices 0 1 2.
const Tri kBase = {{{0, 0, 0}, {2, 0, 0}, {0, 2, 0}}, {0, 1, 2}};

TEST(TriangleOverlap, DisjointAndParallelDoNotOverlap) {
  EXPECT_FALSE(test(kBase, {{{0, 0, 1}, {2, 0, 1}, {0, 2, 1}}, {3, 4, 5}}).overlap);
  EXPECT_FALSE(test(kBase, {{{3, 3, -1}, {3, 3, 1}, {4, 4, 0}}, {3, 4, 5}}).overlap);
}

TEST(TriangleOverlap, AnEdgeThroughTheInsideIsFoundWhereItCrosses) {
  const Tri b = {{{0.5, 0.5, -1}, {0.5, 0.5, 1}, {0.6, 0.6, 0.5}}, {3, 4, 5}};
  const PairOverlap o = test(kBase, b);
  ASSERT_TRUE(o.overlap);
  EXPECT_DOUBLE_EQ(o.near[0], 0.5);
  EXPECT_DOUBLE_EQ(o.near[1], 0.5);
  EXPECT_DOUBLE_EQ(o.near[2], 0.0);
  EXPECT_TRUE(test(b, kBase).overlap);  // either order
}

TEST(TriangleOverlap, ContactIsNoOverlapACrossingIs) {
  // b's corner on base's inside: the triangles touch.
  EXPECT_FALSE(test(kBase, {{{0.5, 0.5, 0}, {0.5, 0.5, 1}, {1, 0.5, 1}}, {3, 4, 5}}).overlap);
  // ... and a hair below it b goes through.
  const PairOverlap o = test(kBase, {{{0.5, 0.5, -1e-9}, {0.5, 0.5, 1}, {1, 0.5, 1}}, {3, 4, 5}});
  EXPECT_TRUE(o.overlap);
  EXPECT_NEAR(o.near[2], 0.0, 1e-15);
  // Coplanar, along a common edge of other vertices.
  EXPECT_FALSE(test(kBase, {{{2, 0, 0}, {2, 2, 0}, {0, 2, 0}}, {3, 4, 5}}).overlap);
}

TEST(TriangleOverlap, CoplanarTrianglesOverlapByArea) {
  EXPECT_TRUE(test(kBase, {{{0.5, 0.5, 0}, {3, 0.5, 0}, {0.5, 3, 0}}, {3, 4, 5}}).overlap);
  EXPECT_TRUE(test(kBase, {{{0.2, 0.2, 0}, {0.4, 0.2, 0}, {0.2, 0.4, 0}}, {3, 4, 5}}).overlap);  // inside
  EXPECT_FALSE(test(kBase, {{{2, 2, 0}, {3, 2, 0}, {2, 3, 0}}, {3, 4, 5}}).overlap);
}

TEST(TriangleOverlap, ASharedVertexAloneIsNoOverlap) {
  // A fan around vertex 0, bent out of the plane and in it.
  EXPECT_FALSE(test(kBase, {{{0, 0, 0}, {-1, 0, 0.5}, {0, -1, 0.5}}, {0, 3, 4}}).overlap);
  EXPECT_FALSE(test(kBase, {{{0, 0, 0}, {-1, 0, 0}, {0, -1, 0}}, {0, 3, 4}}).overlap);
  EXPECT_FALSE(test(kBase, {{{0, 0, 0}, {0, 2, 0.1}, {-1, 1, 0}}, {0, 3, 4}}).overlap);
}

TEST(TriangleOverlap, ASharedVertexStillCatchesACrossing) {
  // The far edge of b passes through base's inside.
  const PairOverlap o = test(kBase, {{{0, 0, 0}, {0.5, 0.5, -1}, {0.5, 0.5, 1}}, {0, 3, 4}});
  ASSERT_TRUE(o.overlap);
  EXPECT_DOUBLE_EQ(o.near[2], 0.0);
  // In one plane: b's wedge at vertex 0 (45 to 135 degrees) overlaps base's (0 to 90).
  EXPECT_TRUE(test(kBase, {{{0, 0, 0}, {1, 1, 0}, {-1, 1, 0}}, {0, 3, 4}}).overlap);
  // The same wedge as base's, shorter.
  EXPECT_TRUE(test(kBase, {{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {0, 3, 4}}).overlap);
}

TEST(TriangleOverlap, ASharedEdgeOverlapsOnlyWhenFolded) {
  // Across the edge (0, 1): the mesh's usual neighbour, flat and bent.
  EXPECT_FALSE(test(kBase, {{{2, 0, 0}, {0, 0, 0}, {1, -1, 0}}, {1, 0, 3}}).overlap);
  EXPECT_FALSE(test(kBase, {{{2, 0, 0}, {0, 0, 0}, {1, 0.5, 0.01}}, {1, 0, 3}}).overlap);
  // Folded onto base.
  EXPECT_TRUE(test(kBase, {{{2, 0, 0}, {0, 0, 0}, {1, 0.5, 0}}, {1, 0, 3}}).overlap);
}

TEST(TriangleOverlap, TheSameTriangleTwiceOverlaps) {
  EXPECT_TRUE(test(kBase, {{kBase.p[0], kBase.p[2], kBase.p[1]}, {0, 2, 1}}).overlap);
}

TEST(TriangleOverlap, DegenerateTrianglesAreLeftToTheirNeighbours) {
  EXPECT_FALSE(test(kBase, {{{0.5, 0.5, -1}, {0.5, 0.5, 0}, {0.5, 0.5, 1}}, {3, 4, 5}}).overlap);
}

// The largest side of the box around both triangles.
double pair_extent(const Tri& a, const Tri& b) {
  double d = 0;
  for (int k = 0; k < 3; ++k) {
    double lo = INFINITY, hi = -INFINITY;
    for (const Tri* t : {&a, &b})
      for (const Point3& p : t->p) {
        lo = std::min(lo, p[size_t(k)]);
        hi = std::max(hi, p[size_t(k)]);
      }
    d = std::max(d, hi - lo);
  }
  return d;
}

bool apart(const Tri& a, const Tri& b, double extent) {
  return certainly_apart(a.p, triangle_normal(a.p), a.v, b.p, triangle_normal(b.p), b.v, extent);
}

TEST(TriangleOverlap, CertainlyApartDecidesTheClearCasesOnly) {
  const double e = 2.0;
  // A triangle above the base, sharing nothing, a vertex, an edge.
  EXPECT_TRUE(apart(kBase, {{{0, 0, 1}, {1, 0, 1}, {0, 1, 1}}, {3, 4, 5}}, pair_extent(kBase, kBase) + e));
  EXPECT_TRUE(apart(kBase, {{{0, 0, 0}, {1, 0, 1}, {0, 1, 1}}, {0, 4, 5}}, 2 * e));
  EXPECT_TRUE(apart(kBase, {{{2, 0, 0}, {0, 0, 0}, {1, 1, -1}}, {1, 0, 5}}, 2 * e));
  // Folded onto the base along its edge, crossing it, the same triangle:
  // left to triangles_overlap.
  EXPECT_FALSE(apart(kBase, {{{2, 0, 0}, {0, 0, 0}, {1, 1, 0}}, {1, 0, 5}}, 2 * e));
  EXPECT_FALSE(apart(kBase, {{{0.5, 0.5, -1}, {0.5, 0.5, 1}, {3, 3, 0}}, {3, 4, 5}}, 2 * e));
  EXPECT_FALSE(apart(kBase, kBase, 2 * e));
}

TEST(TriangleOverlap, CertainlyApartNeverHidesAnOverlap) {
  // Random pairs sharing 0, 1 or 2 vertices, some far apart, some crossing,
  // some with the second triangle within 1e-16 to 1e-10 of the first's
  // plane: whenever certainly_apart says apart, triangles_overlap finds no
  // overlap, with the exact extent and with a larger one.
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-1, 1), tiny(-1, 1);
  long long decided = 0, overlaps = 0, total = 0;
  for (int i = 0; i < 200000; ++i) {
    Tri a, b;
    for (int k = 0; k < 3; ++k) {
      a.v[k] = k;
      b.v[k] = 3 + k;
      for (int c = 0; c < 3; ++c) {
        a.p[k][size_t(c)] = u(rng);
        b.p[k][size_t(c)] = u(rng);
      }
    }
    const int shared = i % 3;
    for (int k = 0; k < shared; ++k) {  // b's corner k is a's corner k, with b turning the other way
      b.p[k] = a.p[k];
      b.v[k] = a.v[k];
    }
    if (shared == 2) std::swap(b.p[0], b.p[1]), std::swap(b.v[0], b.v[1]);
    if (i % 5 == 0) {  // b's free corners near a's plane
      const Point3 n = triangle_normal(a.p);
      const double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
      for (int k = shared; k < 3; ++k) {
        const Point3 q = b.p[k];
        const double off = ((q[0] - a.p[0][0]) * n[0] + (q[1] - a.p[0][1]) * n[1] + (q[2] - a.p[0][2]) * n[2]) / len;
        const double keep = std::pow(10.0, -16 + 6 * (0.5 + 0.5 * tiny(rng))) * tiny(rng);
        for (int c = 0; c < 3; ++c) b.p[k][size_t(c)] = q[size_t(c)] - (off - keep) * n[size_t(c)] / len;
      }
    }
    const bool overlap = triangles_overlap(a.p, a.v, b.p, b.v).overlap;
    const double d = pair_extent(a, b);
    for (double extent : {d, 1.7 * d}) {
      const bool said = apart(a, b, extent);
      EXPECT_FALSE(said && overlap) << "pair " << i << " (" << shared << " shared) called apart but overlaps";
      decided += said;
      ++total;
    }
    overlaps += overlap;
  }
  EXPECT_GT(overlaps, 1000);          // the sample has overlaps to hide
  EXPECT_GT(decided, total / 4);      // and the test decides a good part of it
}

// Every pair, tested directly.
std::set<std::pair<int32_t, int32_t>> all_pairs(const Mesh& m) {
  std::set<std::pair<int32_t, int32_t>> found;
  auto corner = [&](size_t t, int k) {
    const size_t v = size_t(m.triangles[3 * t + size_t(k)]);
    return Point3{m.points[3 * v], m.points[3 * v + 1], m.points[3 * v + 2]};
  };
  for (size_t a = 0; a < m.triangle_count(); ++a)
    for (size_t b = a + 1; b < m.triangle_count(); ++b) {
      const Point3 pa[3] = {corner(a, 0), corner(a, 1), corner(a, 2)}, pb[3] = {corner(b, 0), corner(b, 1), corner(b, 2)};
      if (triangles_overlap(pa, &m.triangles[3 * a], pb, &m.triangles[3 * b]).overlap)
        found.insert({int32_t(a), int32_t(b)});
    }
  return found;
}

std::set<std::pair<int32_t, int32_t>> grid_pairs(const Mesh& m) {
  std::set<std::pair<int32_t, int32_t>> found;
  for (const OverlapPair& p : find_overlaps(m)) {
    EXPECT_LT(p.a, p.b);
    EXPECT_TRUE(found.insert({p.a, p.b}).second) << "pair " << p.a << ", " << p.b << " twice";
  }
  return found;
}

TEST(MeshOverlap, ClosedAndFlatMeshesDoNotOverlapThemselves) {
  Mesh torus;
  add_torus(torus, 24, 16, 2, 0.7, {0, 0, 0});
  EXPECT_TRUE(find_overlaps(torus).empty());
  EXPECT_NO_THROW(validate_input(torus, "torus"));
  const Mesh flat = plane_grid(30);  // every neighbour coplanar
  EXPECT_TRUE(find_overlaps(flat).empty());
  Mesh tilted = flat;  // coplanar up to rounding
  for (size_t v = 0; v < tilted.vertex_count(); ++v) {
    float* p = &tilted.points[3 * v];
    p[2] = 0.2f * p[0] + 0.3f * p[1] + 0.1f;
    tilted.precise_points.insert(tilted.precise_points.end(), {0.1 * p[0], 0.1 * p[1], 0.1 * p[2]});
  }
  EXPECT_TRUE(find_overlaps(tilted).empty());
}

TEST(MeshOverlap, TheGridFindsExactlyThePairsOfTheDirectTest) {
  Mesh linked;  // two tori through each other, and one apart
  add_torus(linked, 16, 12, 2, 0.5, {0, 0, 0});
  add_torus(linked, 16, 12, 2, 0.5, {1.5, 0.3, 0.2});
  add_torus(linked, 8, 6, 1, 0.3, {10, 0, 0});
  const auto direct = all_pairs(linked);
  EXPECT_GT(direct.size(), 20u);
  EXPECT_EQ(grid_pairs(linked), direct);
  for (const auto& p : direct) {  // only pairs of the first two tori cross
    EXPECT_LT(p.first, 384);
    EXPECT_GE(p.second, 384);
    EXPECT_LT(p.second, 768);
  }
  Mesh fold = plane_grid(12);  // a vertex pulled across its neighbours, in the plane
  fold.points[3 * (5 * 12 + 5)] = 8.5f;
  fold.points[3 * (5 * 12 + 5) + 1] = 5.3f;
  const auto folded = all_pairs(fold);
  EXPECT_FALSE(folded.empty());
  EXPECT_EQ(grid_pairs(fold), folded);
}

// The grid is tested in slabs across its longest axis, each slab's blocks
// numbered densely or, where they would be many times the entries, hashed:
// linked tori turned upright (so that they cross many slabs), once on their
// own and once with a small torus far off along every axis (hashed slabs).
TEST(MeshOverlap, SlabsDenseOrHashedFindExactlyThePairsOfTheDirectTest) {
  Mesh upright;
  add_torus(upright, 16, 12, 2, 0.5, {0, 0, 0});
  add_torus(upright, 16, 12, 2, 0.5, {1.5, 0.3, 0.2});
  for (size_t v = 0; v < upright.vertex_count(); ++v) std::swap(upright.points[3 * v + 1], upright.points[3 * v + 2]);
  const auto direct = all_pairs(upright);
  EXPECT_GT(direct.size(), 20u);
  EXPECT_EQ(grid_pairs(upright), direct);
  Mesh far = upright;
  add_torus(far, 8, 6, 1, 0.3, {3000, 2000, 1000});
  EXPECT_EQ(all_pairs(far), direct);  // the far torus crosses nothing
  EXPECT_EQ(grid_pairs(far), direct);
  // Pulled through the first torus, a copy of the far one crosses it.
  Mesh through = upright;
  add_torus(through, 8, 6, 1, 0.3, {2, 0.1, 0});
  add_torus(through, 8, 6, 1, 0.3, {3000, 2000, 1000});
  const auto crossing = all_pairs(through);
  EXPECT_GT(crossing.size(), direct.size());
  EXPECT_EQ(grid_pairs(through), crossing);
}

TEST(MeshOverlap, OversizedTrianglesAreTestedAgainstEveryBox) {
  // A torus of 384 triangles (cells about its triangles' size), a triangle
  // 40 wide slicing through it (thousands of cells: kept out of the grid),
  // and a second one upright through the first but clear of the torus.
  Mesh m;
  add_torus(m, 16, 12, 2, 0.5, {0, 0, 0});
  const int32_t big = int32_t(m.vertex_count());
  m.points.insert(m.points.end(), {-20, -20, 0.1f, 20, -20, 0.3f, 0, 20, -0.2f});
  m.points.insert(m.points.end(), {-20, 5, -10, 20, 5, -10, 0, 5, 10});
  m.triangles.insert(m.triangles.end(), {big, big + 1, big + 2, big + 3, big + 4, big + 5});
  const auto direct = all_pairs(m);
  EXPECT_EQ(grid_pairs(m), direct);
  size_t slicing = 0;
  for (const auto& p : direct) slicing += p.first < 384 && p.second == 384;
  EXPECT_GT(slicing, 20u);
  EXPECT_EQ(direct.count({384, 385}), 1u);
  EXPECT_EQ(direct.size(), slicing + 1);  // nothing else crosses
}

TEST(MeshOverlap, TheReductionRefusesTheFirstPairByName) {
  Mesh m;
  add_torus(m, 16, 12, 2, 0.5, {0, 0, 0});
  add_torus(m, 16, 12, 2, 0.5, {1.5, 0.3, 0.2});
  const auto direct = all_pairs(m);
  ASSERT_FALSE(direct.empty());
  const auto first = *direct.begin();
  const std::string expected = "torus: the mesh overlaps itself: triangles " + std::to_string(first.first) + " and " +
                               std::to_string(first.second) + " intersect (near ";
  try {
    validate_input(m, "torus");
    ADD_FAILURE() << "accepted";
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(std::string(e.what()).substr(0, expected.size()), expected) << e.what();
  }
}

}  // namespace
}  // namespace isoform::reduce

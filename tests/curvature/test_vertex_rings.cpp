// The one-ring table (VertexRings) on hand-built fans, against the order and
// flags worked out by hand, with up to 8 triangles at a vertex and more;
// and the seed's short path (fit_seed_vertex) against
// fit_vertex, and its four-lane form against it, bit for bit.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <vector>

#include "libcore/curvature/seed_vertex.h"
#include "libcore/curvature/vertex_rings.h"
#include "libcore/mesh_normals.h"
#include "truth.h"

using namespace isoform;

namespace {

std::vector<int32_t> ring_of(const VertexRings& r, int32_t v) { return {r.ring_begin(v), r.ring_end(v)}; }

// Vertex 0 at the centre of `count` triangles (0, k, k + 1) around it, k = 1
// .. count (the last closing back to 1 when closed), points on a circle.
Mesh fan(int count, bool closed) {
  Mesh m;
  m.points = {0, 0, 0};
  const int rim = closed ? count : count + 1;
  for (int k = 0; k < rim; ++k) {
    const double a = 6.283185307179586 * k / (closed ? count : 2 * count);
    m.points.insert(m.points.end(), {float(std::cos(a)), float(std::sin(a)), 0.0f});
  }
  for (int k = 1; k <= count; ++k) m.triangles.insert(m.triangles.end(), {0, k, closed && k == count ? 1 : k + 1});
  return m;
}

}  // namespace

TEST(VertexRings, ClosedFansKeepTheOrderOfFirstMeetingOnBothPaths) {
  for (int count : {3, 6, 8, 9, 12, 40}) {  // 2 x count entries: up to 16 in the table, more by stamps
    const Mesh m = fan(count, true);
    const VertexRings r(m);
    // Triangle k meets k, then k + 1: the rim in order.
    std::vector<int32_t> expected;
    for (int k = 1; k <= count; ++k) expected.push_back(k);
    EXPECT_EQ(ring_of(r, 0), expected) << count << " triangles";
    EXPECT_FALSE(r.on_boundary(0));
    EXPECT_FALSE(r.nonmanifold(0));
    // A rim vertex k (2 <= k < count) meets 0, k + 1 in triangle k - 1's
    // order: (0, k - 1, k) gives 0 then k - 1, then (0, k, k + 1) gives k + 1, 0.
    EXPECT_EQ(ring_of(r, 2), (std::vector<int32_t>{0, 1, 3}));
    EXPECT_TRUE(r.on_boundary(2));  // the rim edges have one triangle each
    EXPECT_FALSE(r.nonmanifold(2));
  }
}

TEST(VertexRings, OpenFansAreBoundaryAndExtraTrianglesNonmanifold) {
  for (int count : {4, 11}) {
    Mesh m = fan(count, false);
    const VertexRings open(m);
    EXPECT_EQ(open.valence(0), size_t(count + 1));
    EXPECT_TRUE(open.on_boundary(0));
    EXPECT_FALSE(open.nonmanifold(0));
    // A third triangle on the inner edge (0, 2): non-manifold at 0 and 2,
    // not at 1 or 3.
    m.points.insert(m.points.end(), {0.5f, 0.5f, 1.0f});
    const int32_t top = int32_t(m.vertex_count()) - 1;
    m.triangles.insert(m.triangles.end(), {0, 2, top});
    const VertexRings three(m);
    EXPECT_TRUE(three.nonmanifold(0));
    EXPECT_TRUE(three.nonmanifold(2));
    EXPECT_FALSE(three.nonmanifold(1));
    EXPECT_FALSE(three.nonmanifold(3));
    EXPECT_EQ(three.ring_begin(0)[three.valence(0) - 1], top);  // met last
  }
}

TEST(VertexRings, TwoFansAtOneVertexAndRepeatedCornersAndIsolatedVertices) {
  // Two triangles touching only at vertex 0 (a bow tie), a degenerate
  // triangle (4, 4, 5) that is ignored and a vertex 6 that no triangle uses.
  Mesh m;
  m.points.assign(3 * 7, 0.0f);
  m.triangles = {0, 1, 2, 0, 3, 4, 4, 4, 5};
  const VertexRings r(m);
  EXPECT_EQ(ring_of(r, 0), (std::vector<int32_t>{1, 2, 3, 4}));
  EXPECT_TRUE(r.nonmanifold(0));
  EXPECT_TRUE(r.on_boundary(0));
  EXPECT_FALSE(r.nonmanifold(1));
  EXPECT_EQ(ring_of(r, 4), (std::vector<int32_t>{0, 3}));
  EXPECT_EQ(r.valence(5), 0u);
  EXPECT_EQ(r.valence(6), 0u);
}

TEST(VertexRings, ConflictDetectionAndMarksGiveTheSameTable) {
  // Where the processor has AVX-512 conflict detection, fans of up to eight
  // triangles are found by it, larger ones by marks; without it, or with
  // vector_instructions false, all by marks. Both must give the same table:
  // compared on a jittered torus with every seventh triangle gone (open
  // fans), and on triangle soups over few vertices (fans of every size,
  // repeated corners, edges with three and more triangles).
  std::vector<truth::Exact> exact;
  Mesh torus = truth::shape_mesh(truth::Shape::Torus, 60, 0.25, 5, exact);
  std::vector<int32_t> kept;
  for (size_t t = 0; t < torus.triangle_count(); ++t)
    if (t % 7 != 3) kept.insert(kept.end(), &torus.triangles[3 * t], &torus.triangles[3 * t + 3]);
  torus.triangles = kept;
  std::vector<Mesh> meshes = {torus};
  uint64_t state = 1;
  auto draw = [&](int below) {
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    return int32_t((state >> 33) % uint64_t(below));
  };
  for (int vertices : {4, 9, 25, 200}) {
    Mesh soup;
    soup.points.assign(3 * size_t(vertices), 0.0f);
    for (int t = 0; t < 3 * vertices; ++t) soup.triangles.insert(soup.triangles.end(), {draw(vertices), draw(vertices), draw(vertices)});
    meshes.push_back(soup);
  }
  size_t boundary = 0, nonmanifold = 0;
  for (const Mesh& m : meshes) {
    const VertexRings fast(m), marks(m, false);
    ASSERT_EQ(fast.vertex_count(), marks.vertex_count());
    EXPECT_EQ(fast.max_valence(), marks.max_valence());
    for (int32_t v = 0; v < int32_t(m.vertex_count()); ++v) {
      ASSERT_EQ(ring_of(fast, v), ring_of(marks, v)) << "vertex " << v;
      EXPECT_EQ(fast.on_boundary(v), marks.on_boundary(v)) << "vertex " << v;
      EXPECT_EQ(fast.nonmanifold(v), marks.nonmanifold(v)) << "vertex " << v;
      boundary += marks.on_boundary(v);
      nonmanifold += marks.nonmanifold(v);
    }
  }
  EXPECT_GT(boundary, 100u);
  EXPECT_GT(nonmanifold, 100u);
}

namespace {

// The same result, bit for bit.
void expect_same(const VertexFitResult& x, const VertexFitResult& y, int32_t v) {
  EXPECT_EQ(x.flags, y.flags) << "vertex " << v;
  EXPECT_EQ(std::memcmp(&x.curvature.k1, &y.curvature.k1, sizeof(double)), 0) << "vertex " << v;
  EXPECT_EQ(std::memcmp(&x.curvature.k2, &y.curvature.k2, sizeof(double)), 0) << "vertex " << v;
  EXPECT_EQ(std::memcmp(x.curvature.d1.data(), y.curvature.d1.data(), 3 * sizeof(double)), 0) << "vertex " << v;
  EXPECT_EQ(std::memcmp(x.curvature.d2.data(), y.curvature.d2.data(), 3 * sizeof(double)), 0) << "vertex " << v;
  EXPECT_EQ(std::memcmp(x.curvature.normal.data(), y.curvature.normal.data(), 3 * sizeof(double)), 0)
      << "vertex " << v;
}

// A jittered torus, an open graph, and the graph with unusable normals
// (zero, NaN) at some vertices, a neighbour moved onto its vertex, and
// float points only.
std::vector<Mesh> seed_meshes() {
  std::vector<truth::Exact> exact;
  Mesh jittered = truth::shape_mesh(truth::Shape::Torus, 40, 0.25, 5, exact);
  estimate_normals(jittered);
  Mesh open = truth::graph_mesh(truth::table41_graphs()[4], 21);
  estimate_normals(open);
  Mesh broken = open;
  broken.normals[3 * 7] = broken.normals[3 * 7 + 1] = broken.normals[3 * 7 + 2] = 0.0f;
  broken.normals[3 * 30 + 1] = std::nanf("");
  const VertexRings rings(broken);
  const int32_t w = *rings.ring_begin(50);
  for (int a = 0; a < 3; ++a) broken.points[3 * size_t(w) + size_t(a)] = broken.points[3 * 50 + size_t(a)];
  broken.precise_points.clear();
  return {jittered, open, broken};
}

}  // namespace

TEST(SeedVertex, ShortPathMatchesFitVertex) {
  for (const Mesh& m : seed_meshes()) {
    const VertexRings rings(m);
    VertexFitScratch a, b;
    for (int32_t v = 0; v < int32_t(m.vertex_count()); ++v)
      expect_same(fit_seed_vertex(m, rings, v, a), fit_vertex(m, rings, v, CurvatureMethod::Seed, 0, b), v);
  }
}

// Four vertices side by side, and the shorter groups at the end of a
// range, give what the one-vertex short path gives.
TEST(SeedVertex, FourLanesMatchOneVertex) {
  for (const Mesh& m : seed_meshes()) {
    const VertexRings rings(m);
    VertexFitScratch a, b;
    const int32_t n = int32_t(m.vertex_count());
    for (int count = 1; count <= 4; ++count)
      for (int32_t first = 0; first + count <= n; first += count) {
        VertexFitResult group[4];
        EXPECT_FALSE(fit_seed_vertices(m, rings, first, count, a, group));
        for (int i = 0; i < count; ++i) expect_same(group[i], fit_seed_vertex(m, rings, first + i, b), first + i);
      }
  }
}

TEST(SeedVertex, FourLanesLeftSideBySideMatchOneVertex) {
  // With lanes asked for, groups the short path settles whole stay side by
  // side; the others come out one by one. Either way each vertex's result
  // is fit_seed_vertex's, and on these meshes both ways occur.
  int side_by_side = 0, one_by_one = 0;
  for (const Mesh& m : seed_meshes()) {
    const VertexRings rings(m);
    VertexFitScratch a, b;
    const int32_t n = int32_t(m.vertex_count());
    for (int32_t first = 0; first + 4 <= n; first += 4) {
      VertexFitResult group[4];
      SeedLanes lanes;
      const bool whole = fit_seed_vertices(m, rings, first, 4, a, group, &lanes);
      (whole ? side_by_side : one_by_one)++;
      for (int i = 0; i < 4; ++i) {
        const VertexFitResult& r = group[i];
        const VertexFitResult one = fit_seed_vertex(m, rings, first + i, b);
        if (!whole) {
          expect_same(r, one, first + i);
          continue;
        }
        // What the store takes: k1, k2, d1, d2 and the flags.
        EXPECT_EQ(lanes.flags[i], one.flags) << "vertex " << first + i;
        EXPECT_EQ(std::memcmp(&lanes.k1[i], &one.curvature.k1, sizeof(double)), 0) << "vertex " << first + i;
        EXPECT_EQ(std::memcmp(&lanes.k2[i], &one.curvature.k2, sizeof(double)), 0) << "vertex " << first + i;
        for (int axis = 0; axis < 3; ++axis) {
          EXPECT_EQ(std::memcmp(&lanes.d1[axis][i], &one.curvature.d1(axis), sizeof(double)), 0) << "vertex " << first + i;
          EXPECT_EQ(std::memcmp(&lanes.d2[axis][i], &one.curvature.d2(axis), sizeof(double)), 0) << "vertex " << first + i;
        }
      }
    }
  }
  EXPECT_GT(side_by_side, 100);
  EXPECT_GT(one_by_one, 0);
}

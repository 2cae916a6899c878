// Section 3.3 on hand-checkable meshes: neighbours, parts, Euler
// characteristic, orientation checks.
#include <gtest/gtest.h>

#include <map>
#include <random>
#include <utility>
#include <vector>

#include "libcore/topology.h"

using namespace isoform;

namespace {

// A regular octahedron, consistently oriented outward.
Mesh octahedron(float shift = 0) {
  Mesh m;
  m.points = {1 + shift, 0, 0, -1 + shift, 0, 0, shift, 1, 0, shift, -1, 0, shift, 0, 1, shift, 0, -1};
  m.triangles = {0, 2, 4, 2, 1, 4, 1, 3, 4, 3, 0, 4, 2, 0, 5, 1, 2, 5, 3, 1, 5, 0, 3, 5};
  return m;
}

// An n x n grid wrapped both ways (a torus's topology), two triangles a
// quad, in the plane: coordinates matter only for degenerate triangles.
Mesh wrapped_grid(int n) {
  Mesh m;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) m.points.insert(m.points.end(), {float(i), float(j), float((i * 7 + j * 3) % 5)});
  auto v = [n](int i, int j) { return int32_t((j % n) * n + (i % n)); };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      m.triangles.insert(m.triangles.end(), {v(i, j), v(i + 1, j), v(i + 1, j + 1), v(i, j), v(i + 1, j + 1), v(i, j + 1)});
  return m;
}

// What compute_neighbours must give, from a map of undirected edges to
// the triangles on them: a neighbour only across an edge of exactly two
// triangles; boundary edges counted per triangle side, non-manifold and
// inconsistently oriented edges once each; Euler characteristic V - E + F.
struct Reference {
  std::vector<int32_t> neighbours;
  long long boundary = 0, nonmanifold = 0, inconsistent = 0, euler = 0;
};

Reference reference_topology(const Mesh& m) {
  std::map<std::pair<int32_t, int32_t>, std::vector<std::pair<int32_t, bool>>> edges;  // (triangle, a < b)
  const size_t nt = m.triangle_count();
  for (size_t t = 0; t < nt; ++t)
    for (int i = 0; i < 3; ++i) {
      const int32_t a = m.triangles[3 * t + size_t(i)], b = m.triangles[3 * t + size_t((i + 1) % 3)];
      edges[{std::min(a, b), std::max(a, b)}].push_back({int32_t(t), a < b});
    }
  Reference r;
  r.neighbours.assign(3 * nt, -1);
  for (const auto& [edge, on] : edges) {
    if (on.size() == 1) ++r.boundary;
    if (on.size() > 2) ++r.nonmanifold;
    if (on.size() != 2) continue;
    if (on[0].second == on[1].second) ++r.inconsistent;
    for (int k = 0; k < 2; ++k) {
      const size_t t = size_t(on[size_t(k)].first);
      for (int i = 0; i < 3; ++i) {
        const int32_t a = m.triangles[3 * t + size_t(i)], b = m.triangles[3 * t + size_t((i + 1) % 3)];
        if (std::min(a, b) == edge.first && std::max(a, b) == edge.second) r.neighbours[3 * t + size_t(i)] = on[size_t(1 - k)].first;
      }
    }
  }
  r.euler = (long long)m.vertex_count() - (long long)edges.size() + (long long)nt;
  return r;
}

}  // namespace

TEST(Topology, OctahedronIsClosedWithThreeNeighboursEach) {
  Mesh m = octahedron();
  compute_topology(m);
  EXPECT_EQ(m.stats.boundary_edges, 0);
  EXPECT_EQ(m.stats.nonmanifold_edges, 0);
  EXPECT_EQ(m.stats.inconsistent_edges, 0);
  EXPECT_EQ(m.stats.euler_characteristic, 2);
  EXPECT_EQ(m.part_count, 1);
  for (int32_t n : m.neighbours) EXPECT_GE(n, 0);
  // Triangle 0 (0,2,4): across (0,2) is triangle 4 (2,0,5); across (2,4) is 1; across (4,0) is 3.
  EXPECT_EQ(m.neighbours[0], 4);
  EXPECT_EQ(m.neighbours[1], 1);
  EXPECT_EQ(m.neighbours[2], 3);
}

TEST(Topology, PartsAreNumberedBySize) {
  Mesh a = octahedron();
  Mesh b = octahedron(5);
  // Drop two triangles of the first octahedron: it becomes the smaller part.
  a.triangles.resize(a.triangles.size() - 6);
  Mesh m;
  m.points = a.points;
  m.points.insert(m.points.end(), b.points.begin(), b.points.end());
  m.triangles = a.triangles;
  for (int32_t v : b.triangles) m.triangles.push_back(v + 6);
  compute_topology(m);
  EXPECT_EQ(m.part_count, 2);
  for (size_t t = 0; t < 6; ++t) EXPECT_EQ(m.parts[t], 1);
  for (size_t t = 6; t < 14; ++t) EXPECT_EQ(m.parts[t], 0);
  EXPECT_EQ(m.stats.boundary_edges, 4);
}

TEST(Topology, FlippedTriangleIsReportedInconsistent) {
  Mesh m = octahedron();
  std::swap(m.triangles[1], m.triangles[2]);
  compute_topology(m);
  EXPECT_EQ(m.stats.inconsistent_edges, 3);
  EXPECT_EQ(m.stats.boundary_edges, 0);
}

TEST(Topology, ThreeTrianglesOnOneEdgeAreNonManifold) {
  Mesh m;
  m.points = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 1};
  m.triangles = {0, 1, 2, 1, 0, 3, 0, 1, 4};
  compute_topology(m);
  EXPECT_EQ(m.stats.nonmanifold_edges, 1);
  EXPECT_EQ(m.neighbours[0], -1);
}

// A triangle (0, 0, 2) on the octahedron: around vertex 0 it is listed
// twice, so the edge (0, 2) has three triangles' sides (non-manifold, no
// neighbour); none of its own edges comes first; it is degenerate.
TEST(Topology, ATriangleThatRepeatsAVertex) {
  Mesh m = octahedron();
  m.triangles.insert(m.triangles.end(), {0, 0, 2});
  compute_neighbours(m);
  EXPECT_EQ(m.stats.degenerate_triangles, 1);
  EXPECT_EQ(m.stats.nonmanifold_edges, 1);
  EXPECT_EQ(m.stats.boundary_edges, 0);
  EXPECT_EQ(m.stats.inconsistent_edges, 0);
  EXPECT_EQ(m.stats.euler_characteristic, 6 - 12 + 9);
  EXPECT_EQ(m.neighbours[0], -1);       // triangle 0 (0, 2, 4) across (0, 2)
  EXPECT_EQ(m.neighbours[3 * 4], -1);   // triangle 4 (2, 0, 5) across (2, 0)
  EXPECT_EQ(m.neighbours[1], 1);        // elsewhere as before
  for (int i = 0; i < 3; ++i) EXPECT_EQ(m.neighbours[3 * 8 + size_t(i)], -1);
}

// Meshes of many stretches with random defects (flipped, dropped and
// repeated triangles) against the edge map: the neighbours and every count.
TEST(Topology, LargeMeshesWithDefectsAgreeWithAnEdgeMap) {
  std::mt19937 random(7);
  for (int round = 0; round < 12; ++round) {
    Mesh m = wrapped_grid(150);  // 45,000 triangles
    const size_t nt = m.triangle_count();
    std::uniform_int_distribution<size_t> pick(0, nt - 1);
    for (int k = 0; k < round; ++k) {
      const size_t t = pick(random);
      std::swap(m.triangles[3 * t], m.triangles[3 * t + 1]);
    }
    for (int k = 0; k < round; ++k) {
      const size_t t = pick(random);
      m.triangles.insert(m.triangles.end(), m.triangles.begin() + long(3 * t), m.triangles.begin() + long(3 * t + 3));
    }
    for (int k = 0; k < round % 4; ++k) {
      const long t = long(pick(random));
      m.triangles.erase(m.triangles.begin() + 3 * t, m.triangles.begin() + 3 * t + 3);
    }
    const Reference r = reference_topology(m);
    compute_neighbours(m);
    EXPECT_EQ(m.neighbours, r.neighbours) << "round " << round;
    EXPECT_EQ(m.stats.boundary_edges, r.boundary) << "round " << round;
    EXPECT_EQ(m.stats.nonmanifold_edges, r.nonmanifold) << "round " << round;
    EXPECT_EQ(m.stats.inconsistent_edges, r.inconsistent) << "round " << round;
    EXPECT_EQ(m.stats.euler_characteristic, r.euler) << "round " << round;
    if (round == 0) {
      EXPECT_EQ(r.euler, 0);  // a torus
      EXPECT_EQ(r.boundary + r.nonmanifold + r.inconsistent, 0);
    }
  }
}

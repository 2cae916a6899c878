// Section 3.3 on hand-checkable meshes: neighbours, parts, Euler
// characteristic, orientation checks.
#include <gtest/gtest.h>

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

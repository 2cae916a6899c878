// Dropping parts, on a hand-made mesh of four parts: a cube of side 2
// (12 triangles, volume 8), an octahedron of radius 1 (8 triangles, volume
// 4/3), a tetrahedron (4 triangles, volume 1/6) and one loose triangle
// (open: no volume), with normals and colours per vertex to follow.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "libcore/part_filter.h"
#include "libcore/topology.h"

using namespace isoform;

namespace {

// Appends a closed shape given by its corners and outward triangles.
void add_shape(Mesh& m, const std::vector<float>& corners, const std::vector<int32_t>& triangles, float dx) {
  const int32_t base = int32_t(m.vertex_count());
  for (size_t i = 0; i < corners.size(); ++i) m.points.push_back(corners[i] + (i % 3 == 0 ? dx : 0.0f));
  for (int32_t v : triangles) m.triangles.push_back(base + v);
}

Mesh four_parts() {
  Mesh m;
  // The tetrahedron first and the loose triangle second, so that parts are
  // renumbered by size and vertices are compacted across the gaps.
  add_shape(m, {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1}, {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3}, 20);
  add_shape(m, {0, 0, 5, 1, 0, 5, 0, 1, 5}, {0, 1, 2}, 30);
  add_shape(m, {1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1},
            {0, 2, 4, 2, 1, 4, 1, 3, 4, 3, 0, 4, 2, 0, 5, 1, 2, 5, 3, 1, 5, 0, 3, 5}, 10);
  add_shape(m, {-1, -1, -1, 1, -1, -1, 1, 1, -1, -1, 1, -1, -1, -1, 1, 1, -1, 1, 1, 1, 1, -1, 1, 1},
            {0, 2, 1, 0, 3, 2, 4, 5, 6, 4, 6, 7, 0, 1, 5, 0, 5, 4, 2, 3, 7, 2, 7, 6, 1, 2, 6, 1, 6, 5, 3, 0, 4, 3, 4, 7},
            0);
  for (size_t v = 0; v < m.vertex_count(); ++v) {
    m.normals.insert(m.normals.end(), {float(v), 0, 0});  // tags that must follow their vertex
    m.colors.insert(m.colors.end(), {uint8_t(v), 0, 0, 255});
  }
  compute_topology(m);
  return m;
}

// Every vertex is used, and each kept vertex still has its tag.
void expect_compact_and_tagged(const Mesh& m) {
  std::vector<bool> used(m.vertex_count(), false);
  for (int32_t v : m.triangles) used[size_t(v)] = true;
  for (size_t v = 0; v < used.size(); ++v) EXPECT_TRUE(used[v]) << "vertex " << v << " unused";
  ASSERT_EQ(m.normals.size(), m.points.size());
  ASSERT_EQ(m.colors.size(), 4 * m.vertex_count());
  for (size_t v = 0; v < m.vertex_count(); ++v) EXPECT_EQ(float(m.colors[4 * v]), m.normals[3 * v]);
}

TEST(PartFilter, VolumesOfClosedPartsAndNoneForOpenOnes) {
  const Mesh m = four_parts();
  ASSERT_EQ(m.part_count, 4);
  const std::vector<double> volume = part_volumes(m);
  // Parts by size: cube, octahedron, tetrahedron, loose triangle.
  EXPECT_NEAR(volume[0], 8.0, 1e-12);
  EXPECT_NEAR(volume[1], 4.0 / 3.0, 1e-12);
  EXPECT_NEAR(volume[2], 1.0 / 6.0, 1e-12);
  EXPECT_EQ(volume[3], -1.0);
}

TEST(PartFilter, ByTriangleCount) {
  Mesh m = four_parts();
  PartFilter filter;
  filter.min_triangles = 5;
  const PartFilterResult r = filter_parts(m, filter);
  EXPECT_EQ(r.parts_before, 4);
  EXPECT_EQ(r.parts_after, 2);
  EXPECT_EQ(r.triangles_before, 25);
  EXPECT_EQ(r.triangles_after, 20);
  EXPECT_EQ(m.vertex_count(), 14u);  // the octahedron's 6 and the cube's 8
  EXPECT_EQ(m.stats.euler_characteristic, 4);
  EXPECT_EQ(m.stats.boundary_edges, 0);
  EXPECT_EQ(m.parts.size(), 20u);
  expect_compact_and_tagged(m);
}

TEST(PartFilter, ByVolumeKeepsOpenParts) {
  Mesh m = four_parts();
  PartFilter filter;
  filter.min_volume = 2.0;
  const PartFilterResult r = filter_parts(m, filter);
  EXPECT_EQ(r.parts_after, 2);  // the cube and the loose triangle
  EXPECT_EQ(r.triangles_after, 13);
  EXPECT_EQ(m.stats.boundary_edges, 3);
  expect_compact_and_tagged(m);
}

TEST(PartFilter, TheLargestAndNothingToDrop) {
  Mesh m = four_parts();
  PartFilter filter;
  filter.largest = 1;
  EXPECT_EQ(filter_parts(m, filter).triangles_after, 12);
  EXPECT_EQ(m.vertex_count(), 8u);
  EXPECT_EQ(m.stats.euler_characteristic, 2);
  expect_compact_and_tagged(m);
  const PartFilterResult again = filter_parts(m, PartFilter{});
  EXPECT_EQ(again.parts_after, again.parts_before);
  EXPECT_EQ(m.triangle_count(), 12u);
}

}  // namespace

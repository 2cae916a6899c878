// The contour of real files: the same arrays on one thread and on two, and
// the brick-by-brick neighbours and parts equal to those compute_topology
// finds on the finished mesh.
#include <gtest/gtest.h>

#include "libcore/contour/contour.h"
#include "libcore/topology.h"
#include "test_support.h"
#include "vdbio/vdb_file.h"

namespace isoform::vdbio {
namespace {

Mesh contour_file(const std::string& name, double iso, int threads) {
  const auto file = open_vdb(test::data_file(name));
  ContourOptions o;
  o.isovalue = iso;
  o.auto_isovalue = false;
  o.threads = threads;
  return contour(*file->load(0), o, Progress(nullptr));
}

void expect_same_topology(const Mesh& m) {
  Mesh again;
  again.points = m.points;
  again.triangles = m.triangles;
  compute_topology(again);
  EXPECT_EQ(m.neighbours, again.neighbours);
  EXPECT_EQ(m.parts, again.parts);
  EXPECT_EQ(m.part_count, again.part_count);
  EXPECT_EQ(m.stats.boundary_edges, again.stats.boundary_edges);
  EXPECT_EQ(m.stats.nonmanifold_edges, again.stats.nonmanifold_edges);
  EXPECT_EQ(m.stats.inconsistent_edges, again.stats.inconsistent_edges);
  EXPECT_EQ(m.stats.degenerate_triangles, again.stats.degenerate_triangles);
  EXPECT_EQ(m.stats.euler_characteristic, again.stats.euler_characteristic);
}

TEST(ContourRealData, OneAndTwoThreadsGiveIdenticalArrays) {
  for (const auto& [name, iso] : {std::pair<const char*, double>{"cube.vdb", 0.0}, {"smoke.vdb", 0.5}}) {
    SCOPED_TRACE(name);
    const Mesh a = contour_file(name, iso, 1);
    const Mesh b = contour_file(name, iso, 2);
    ASSERT_GT(a.triangle_count(), 0u);
    EXPECT_EQ(a.points, b.points);
    EXPECT_EQ(a.normals, b.normals);
    EXPECT_EQ(a.triangles, b.triangles);
    EXPECT_EQ(a.neighbours, b.neighbours);
    EXPECT_EQ(a.parts, b.parts);
    EXPECT_EQ(a.part_count, b.part_count);
  }
}

TEST(ContourRealData, TopologyMatchesTheWholeMeshAlgorithm) {
  // smoke.vdb has 707 parts, and parts joined only across brick faces.
  const Mesh smoke = contour_file("smoke.vdb", 0.5, 2);
  EXPECT_EQ(smoke.part_count, 707);
  expect_same_topology(smoke);
  const Mesh cube = contour_file("cube.vdb", 0.0, 2);
  EXPECT_EQ(cube.triangle_count(), 586088u);
  EXPECT_EQ(cube.part_count, 1);
  expect_same_topology(cube);
}

}  // namespace
}  // namespace isoform::vdbio

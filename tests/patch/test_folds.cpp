// Folds of the side-vertex surface (orientation.h): a triangle folded over
// its neighbour (consistent winding, face normal against the data normals)
// is counted as inverted, its shared edge as folded, and there the two
// patches share the tangent plane with opposite orientations; the same
// mesh unfolded has neither. The comparison's report counts the folded edge
// and gives the tangent-plane gap apart from the oriented normal gap.
#include <gtest/gtest.h>

#include <cmath>

#include "libcore/compare/compare.h"
#include "libcore/patch/orientation.h"
#include "libcore/topology.h"

namespace isoform::patch {
namespace {

// Triangles (0, 1, 2) and (1, 0, 3) in the plane z = 0, normals +z; vertex 3
// on the side of vertex 2 (folded) or across the edge 0-1 (not folded).
Mesh two_triangles(bool folded) {
  Mesh m;
  const float y3 = folded ? 0.5f : -0.5f;
  m.points = {0, 0, 0, 1, 0, 0, 0.3f, 1, 0, 0.6f, y3, 0};
  m.normals = {0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1};
  m.triangles = {0, 1, 2, 1, 0, 3};
  return m;
}

// Both patches at the point f of the way from vertex 0 to vertex 1.
void edge_samples(const SideVertexSurface& s, double f, SurfaceSample& a, SurfaceSample& b) {
  ASSERT_TRUE(s.evaluate(0, f, 0.0, a));        // triangle (0, 1, 2): weight u on vertex 1
  ASSERT_TRUE(s.evaluate(1, 1.0 - f, 0.0, b));  // triangle (1, 0, 3): weight 1 - u - v on vertex 1
}

TEST(Folds, AFoldedTriangleIsInvertedAndItsSharedEdgeFolded) {
  const SideVertexSurface s(two_triangles(true), {});
  EXPECT_EQ(s.stats().inverted_triangles, 1);
  EXPECT_TRUE(inverted_triangle(s, 1));
  EXPECT_FALSE(inverted_triangle(s, 0));
  const FoldReport r = find_folds(s);
  EXPECT_EQ(r.inverted_triangles, 1);
  ASSERT_EQ(r.folded_edges, 1);
  ASSERT_EQ(r.edges.size(), 1u);
  const size_t e = size_t(r.edges[0]);
  EXPECT_EQ(s.edge_vertex(e, 0), 0);
  EXPECT_EQ(s.edge_vertex(e, 1), 1);
  for (double f : {0.25, 0.5, 0.75}) {
    SurfaceSample a, b;
    edge_samples(s, f, a, b);
    const V3d na = V3d::from(a.normal), nb = V3d::from(b.normal);
    EXPECT_LT(norm(V3d::from(a.point) - V3d::from(b.point)), 1e-14);
    EXPECT_LT(norm(cross(na, nb)), 1e-12);  // one tangent plane ...
    EXPECT_LT(dot(na, nb), -1.0 + 1e-12);   // ... opposite orientations
  }
}

TEST(Folds, TheUnfoldedMeshHasNone) {
  const SideVertexSurface s(two_triangles(false), {});
  EXPECT_EQ(s.stats().inverted_triangles, 0);
  const FoldReport r = find_folds(s);
  EXPECT_EQ(r.inverted_triangles, 0);
  EXPECT_EQ(r.folded_edges, 0);
  EXPECT_TRUE(r.edges.empty());
  SurfaceSample a, b;
  edge_samples(s, 0.5, a, b);
  EXPECT_GT(dot(V3d::from(a.normal), V3d::from(b.normal)), 1.0 - 1e-12);
}

compare::SurfaceMetrics compared(Mesh m) {
  compute_neighbours(m);
  const SideVertexSurface s(m, {});
  compare::CompareSettings settings;
  settings.level = 4;
  const compare::CompareResult r = compare::compare_surfaces(m, {{"side-vertex", &s}}, nullptr, settings, Progress(nullptr));
  EXPECT_EQ(r.surfaces.size(), 1u);
  return r.surfaces.at(0);
}

TEST(Folds, TheComparisonReportCountsFoldedEdgesAndTheTangentPlaneGap) {
  const compare::SurfaceMetrics folded = compared(two_triangles(true));
  EXPECT_EQ(folded.folded_edges, 1);
  EXPECT_GT(folded.normal_gap.count, 0);
  EXPECT_NEAR(folded.normal_gap.max, M_PI, 1e-12);
  EXPECT_LT(folded.tangent_plane_gap.max, 1e-12);
  const compare::SurfaceMetrics flat = compared(two_triangles(false));
  EXPECT_EQ(flat.folded_edges, 0);
  EXPECT_LT(flat.normal_gap.max, 1e-12);
  EXPECT_LT(flat.tangent_plane_gap.max, 1e-12);
}

}  // namespace
}  // namespace isoform::patch

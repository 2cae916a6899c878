// Tessellation of the side-vertex surface: exact counts, closed and manifold
// output for closed input, samples on the surface, shared edges welded.
#include <gtest/gtest.h>

#include <cmath>

#include "libcore/errors.h"
#include "libcore/patch/tessellate.h"
#include "libcore/topology.h"
#include "patch_fixtures.h"

namespace isoform::patch {
namespace {

TEST(Tessellate, ClosedInputGivesAClosedManifoldMeshWithExactCounts) {
  const Mesh base = test::icosahedron();
  const SideVertexSurface s(base, {});
  for (int level : {0, 1, 3}) {
    SCOPED_TRACE(level);
    TessellationStats st;
    const Mesh m = tessellate(s, level, Progress(nullptr), &st);
    const size_t n = size_t(1) << level;
    EXPECT_EQ(m.vertex_count(), 12 + 30 * (n - 1) + 20 * (n - 1) * (n - 2) / 2);
    EXPECT_EQ(m.triangle_count(), 20 * n * n);
    EXPECT_EQ(m.stats.boundary_edges, 0);
    EXPECT_EQ(m.stats.nonmanifold_edges, 0);
    EXPECT_EQ(m.stats.inconsistent_edges, 0);
    EXPECT_EQ(m.stats.degenerate_triangles, 0);
    EXPECT_EQ(m.stats.euler_characteristic, 2);
    EXPECT_EQ(m.part_count, 1);
    EXPECT_EQ(st.flat_samples, 0);
    EXPECT_EQ(st.reversed_samples, 0);
  }
}

TEST(Tessellate, SamplesLieOnTheSurfaceWithItsNormals) {
  const Mesh base = test::skewed_octahedron();
  const SideVertexSurface s(base, {});
  const int level = 2, n = 4;
  const Mesh m = tessellate(s, level, Progress(nullptr));
  EXPECT_EQ(m.stats.boundary_edges, 0);
  EXPECT_EQ(m.stats.nonmanifold_edges, 0);
  // Each base triangle's grid sample (i, j) is output vertex ... of its
  // triangles; check all via the triangles of base triangle t.
  for (size_t t = 0; t < base.triangle_count(); ++t) {
    const int32_t* tri = &m.triangles[3 * t * n * n];
    // The first small triangle is samples (0,0), (1,0), (0,1).
    const double uv[3][2] = {{0, 0}, {1.0 / n, 0}, {0, 1.0 / n}};
    for (int k = 0; k < 3; ++k) {
      SurfaceSample x;
      ASSERT_TRUE(s.evaluate(t, uv[k][0], uv[k][1], x));
      const size_t v = size_t(tri[k]);
      const V3d p(m.precise_points[3 * v], m.precise_points[3 * v + 1], m.precise_points[3 * v + 2]);
      EXPECT_LT(norm(p - V3d::from(x.point)), 1e-12);
      const V3d nn(m.normals[3 * v], m.normals[3 * v + 1], m.normals[3 * v + 2]);
      EXPECT_LT(norm(nn - V3d::from(x.normal)), 1e-6);
    }
  }
}

TEST(Tessellate, NonManifoldEdgesStaySharedAndOppositeNormalsStayFinite) {
  // Three triangles on the edge 0-1 (a book of three pages).
  Mesh m;
  m.precise_points = {0, 0, 0, 1, 0, 0, 0.5, 1, 0, 0.5, -0.5, 0.8, 0.5, -0.5, -0.8};
  m.points.assign(m.precise_points.begin(), m.precise_points.end());
  m.normals = {0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0.8, 0.6, 0, 0.8, -0.6};
  m.triangles = {0, 1, 2, 1, 0, 3, 0, 1, 4};
  compute_topology(m);
  ASSERT_EQ(m.stats.nonmanifold_edges, 1);
  const Mesh t = tessellate(SideVertexSurface(m, {}), 2, Progress(nullptr));
  EXPECT_EQ(t.stats.nonmanifold_edges, 4);  // the shared edge's 4 segments, welded
  EXPECT_EQ(t.vertex_count(), 5 + 7 * 3 + 3 * 3);
  // Opposite normals on an edge: a defined, finite tessellation.
  Mesh o = test::tetrahedron();
  for (int a = 0; a < 3; ++a) o.normals[3 + a] = -o.normals[a];
  const Mesh to = tessellate(SideVertexSurface(o, {}), 3, Progress(nullptr));
  for (double c : to.precise_points) ASSERT_TRUE(std::isfinite(c));
  for (float c : to.normals) ASSERT_TRUE(std::isfinite(c));
  EXPECT_EQ(to.stats.boundary_edges, 0);
}

TEST(Tessellate, RefusesLevelsOutOfRangeAndStopsWhenCancelled) {
  const SideVertexSurface s(test::tetrahedron(), {});
  EXPECT_THROW(tessellate(s, -1, Progress(nullptr)), InvalidArgument);
  EXPECT_THROW(tessellate(s, kMaxTessellationLevel + 1, Progress(nullptr)), InvalidArgument);
  isoform_progress p{};
  p.cancel = 1;
  EXPECT_THROW(tessellate(s, 3, Progress(&p)), Cancelled);
}

}  // namespace
}  // namespace isoform::patch

// The side-vertex surface over real contours (ISOFORM_SHARED_DATA; a missing
// file fails): tangent-plane continuity along every shared edge, and a closed
// manifold tessellation, for both blends.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "libcore/contour/contour.h"
#include "libcore/patch/tessellate.h"
#include "vdbio/vdb_file.h"

namespace isoform::patch {
namespace {

Mesh contour_file(const std::string& name, double iso) {
  const std::string path = std::string(ISOFORM_SHARED_DATA) + "/" + name;
  EXPECT_TRUE(std::filesystem::is_regular_file(path)) << "missing test data: " << path;
  const auto file = vdbio::open_vdb(path);
  ContourOptions o;
  o.isovalue = iso;
  o.auto_isovalue = false;
  return contour(*file->load(0), o, Progress(nullptr));
}

// Largest angle (radians) between the two patches' normals at `samples` - 1
// points inside every interior edge; counts the samples compared.
double edge_normal_gap(const SideVertexSurface& s, const Mesh& m, int samples, long& compared) {
  double worst = 0.0;
  compared = 0;
  auto bary_of = [&](size_t tri, int32_t from, int32_t to, double f, double& u, double& v) {
    double b[3] = {0, 0, 0};
    for (int k = 0; k < 3; ++k) {
      if (m.triangles[3 * tri + k] == from) b[k] = 1 - f;
      if (m.triangles[3 * tri + k] == to) b[k] = f;
    }
    u = b[1];
    v = b[2];
  };
  for (size_t t = 0; t < m.triangle_count(); ++t)
    for (int i = 0; i < 3; ++i) {
      const int32_t other = m.neighbours[3 * t + i];
      if (other < 0 || size_t(other) < t) continue;
      const int32_t a = m.triangles[3 * t + i], b = m.triangles[3 * t + (i + 1) % 3];
      for (int k = 1; k < samples; ++k) {
        const double f = double(k) / samples;
        double u1, v1, u2, v2;
        bary_of(t, a, b, f, u1, v1);
        bary_of(size_t(other), a, b, f, u2, v2);
        SurfaceSample x, y;
        if (!s.evaluate_order(t, u1, v1, x, false) || !s.evaluate_order(size_t(other), u2, v2, y, false)) {
          ADD_FAILURE() << "undefined at edge " << a << "-" << b;
          return M_PI;
        }
        const V3d nx = V3d::from(x.normal), ny = V3d::from(y.normal);
        worst = std::max(worst, std::atan2(norm(cross(nx, ny)), dot(nx, ny)));
        ++compared;
      }
    }
  return worst;
}

TEST(PatchRealData, SphereContourIsTangentPlaneContinuousAndTessellatesClosed) {
  const Mesh m = contour_file("sphere.vdb", 0.0);
  ASSERT_GT(m.triangle_count(), 1000u);
  ASSERT_EQ(m.stats.boundary_edges, 0);
  for (Blend b : {Blend::Squared, Blend::Printed}) {
    PatchOptions o;
    o.blend = b;
    const SideVertexSurface s(m, o);
    long compared = 0;
    const double gap = edge_normal_gap(s, m, 4, compared);
    std::printf("sphere.vdb contour, %s blend: %zu triangles, largest normal gap %.3g rad over %ld edge samples\n",
                b == Blend::Squared ? "squared" : "printed", m.triangle_count(), gap, compared);
    EXPECT_LT(gap, 1e-6);
    EXPECT_EQ(compared, long(m.triangle_count()) * 3 / 2 * 3);
    TessellationStats st;
    const Mesh t = tessellate(s, 1, Progress(nullptr), &st);
    EXPECT_EQ(t.triangle_count(), 4 * m.triangle_count());
    EXPECT_EQ(t.stats.boundary_edges, 0);
    EXPECT_EQ(t.stats.nonmanifold_edges, 0);
    EXPECT_EQ(t.stats.inconsistent_edges, 0);
    EXPECT_EQ(t.stats.euler_characteristic, m.stats.euler_characteristic);
    EXPECT_EQ(st.flat_samples, 0);
  }
}

TEST(PatchRealData, CubeContourWithSharpEdgesIsTangentPlaneContinuous) {
  // The hard case: normals turn by 90 degrees across the cube's edges.
  const Mesh m = contour_file("cube.vdb", 0.0);
  const SideVertexSurface s(m, {});
  long compared = 0;
  const double gap = edge_normal_gap(s, m, 2, compared);
  std::printf("cube.vdb contour: %zu triangles, %lld non-convex edges, largest normal gap %.3g rad\n",
              m.triangle_count(), s.stats().nonconvex_edges, gap);
  EXPECT_LT(gap, 1e-6);
  EXPECT_GT(compared, 0);
}

}  // namespace
}  // namespace isoform::patch

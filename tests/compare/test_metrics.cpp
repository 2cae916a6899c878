// The comparison metrics on cases checkable by hand: the flat octahedron
// against the unit sphere, the Loop surface of a regular torus, the lattice
// and its watertight tessellation, the references' exact distances.
#include <cmath>
#include <set>

#include <gtest/gtest.h>

#include "compare_meshes.h"
#include "libcore/compare/compare.h"
#include "libcore/compare/lattice.h"
#include "libcore/compare/linear_surface.h"
#include "libcore/compare/loop_surface.h"
#include "libcore/compare/surface_geometry.h"
#include "libcore/errors.h"
#include "libcore/topology.h"

namespace isoform::test {
namespace {

using namespace isoform::compare;

CompareResult run(const Mesh& m, const std::vector<NamedSurface>& s, const Reference* ref, int level) {
  CompareSettings settings;
  settings.level = level;
  return compare_surfaces(m, s, ref, settings, Progress(nullptr));
}

TEST(CompareMetrics, LinearOctahedronAgainstTheUnitSphere) {
  const Mesh m = octahedron();
  auto linear = make_linear_surface(m);
  auto sphere = make_sphere_reference({0, 0, 0}, 1.0);
  const CompareResult r = run(m, {{"linear", linear.get()}}, sphere.get(), 3);
  ASSERT_EQ(r.surfaces.size(), 1u);
  const SurfaceMetrics& s = r.surfaces[0];
  EXPECT_EQ(s.samples, 8 * 10);  // (3+1)(3+2)/2 lattice points per face
  EXPECT_EQ(s.failed_samples, 0);
  // The farthest point of a face from the sphere is its centre (1/3, 1/3),
  // a lattice point at level 3: 1 - 1/sqrt(3).
  EXPECT_NEAR(s.deviation.max, 1.0 - 1.0 / std::sqrt(3.0), 1e-15);
  // Vertices lie on the sphere; the flat surface interpolates them.
  EXPECT_EQ(s.data_point_error.count, 6);
  EXPECT_EQ(s.data_point_error.max, 0.0);
  // Neighbouring faces meet at the dihedral angle: normals differ by acos(1/3).
  EXPECT_EQ(s.normal_gap.count, 12 * 3);
  EXPECT_NEAR(s.normal_gap.max, std::acos(1.0 / 3.0), 1e-14);
  EXPECT_NEAR(s.normal_gap.rms, std::acos(1.0 / 3.0), 1e-14);
  EXPECT_LT(s.position_gap.max, 1e-15);
  EXPECT_EQ(s.mean_curvature.p50, 0.0);
  EXPECT_EQ(s.mean_curvature_jump.max, 0.0);
  // |0 - 1/r| everywhere.
  EXPECT_NEAR(s.mean_curvature_error.rms, 1.0, 1e-15);
  EXPECT_EQ(s.tessellation_triangles, 8 * 9);
  // The sample table holds every sample: deviation 0 at corners and
  // 1 - 1/sqrt(3) at the face centre.
  ASSERT_EQ(r.rows.size(), 80u);
  for (size_t i = 0; i < r.rows.size(); ++i) {
    const SampleRow& row = r.rows[i];
    const double dev = r.values[0][i].deviation;
    if ((row.u == 0 && row.v == 0) || row.u == 1 || row.v == 1) {
      EXPECT_NEAR(dev, 0.0, 1e-15);
    }
    if (std::abs(row.u - 1.0 / 3) < 1e-12 && std::abs(row.v - 1.0 / 3) < 1e-12) {
      EXPECT_NEAR(dev, 1.0 - 1.0 / std::sqrt(3.0), 1e-15);
    }
  }
}

TEST(CompareMetrics, TessellationIsWatertightWithSharedVertices) {
  const Mesh m = octahedron();
  auto linear = make_linear_surface(m);
  const int k = 4;
  const CompareResult r = run(m, {{"linear", linear.get()}}, nullptr, k);
  Mesh t = r.tessellations[0];
  // V = 6 corners + 12 edges * (k - 1) + 8 faces * (k - 1)(k - 2)/2; closed.
  EXPECT_EQ(t.vertex_count(), size_t(6 + 12 * (k - 1) + 8 * (k - 1) * (k - 2) / 2));
  EXPECT_EQ(t.triangle_count(), size_t(8 * k * k));
  compute_neighbours(t);
  EXPECT_EQ(t.stats.boundary_edges, 0);
  EXPECT_EQ(t.stats.nonmanifold_edges, 0);
  EXPECT_EQ(t.stats.inconsistent_edges, 0);
  EXPECT_EQ(t.stats.euler_characteristic, 2);
  EXPECT_TRUE(r.reference_kind == "none" && r.surfaces[0].deviation.count == 0);
}

TEST(CompareMetrics, LoopOfARegularTorusIsC1AndShrinksIntoTheTorus) {
  const Mesh m = regular_torus(24, 12, 2.0, 0.7);
  std::string error;
  auto loop = make_loop_surface(m, {}, error);
  ASSERT_TRUE(loop) << error;
  auto linear = make_linear_surface(m);
  auto torus = make_torus_reference({0, 0, 0}, 2.0, 0.7);
  const CompareResult r = run(m, {{"linear", linear.get()}, {"loop", loop.get()}}, torus.get(), 6);
  const SurfaceMetrics& flat = r.surfaces[0];
  const SurfaceMetrics& smooth = r.surfaces[1];
  EXPECT_LT(smooth.normal_gap.max, 1e-9);
  EXPECT_GT(flat.normal_gap.max, 0.1);
  EXPECT_LT(smooth.position_gap.max, 1e-12);
  // Loop does not interpolate; the flat surface does.
  EXPECT_EQ(flat.data_point_error.max, 0.0);
  EXPECT_GT(smooth.data_point_error.mean, 0.01);
  // Box splines are C2: H does not jump across edges of regular patches.
  EXPECT_LT(smooth.mean_curvature_jump.max, 1e-6);
  // Loop's limit points are averages of neighbours, so on this convex-in-
  // the-tube data the surface shrinks away from the torus by more than the
  // flat chords do (measured: RMS 0.038 against 0.019); its H is near the
  // torus's (tube 1/0.7 and the circle around z), where the flat one has 0.
  EXPECT_GT(smooth.deviation.rms, flat.deviation.rms);
  EXPECT_LT(smooth.mean_curvature_error.rms, 0.1 * flat.mean_curvature_error.rms);
  RecordProperty("loop_deviation_rms", std::to_string(smooth.deviation.rms));
  RecordProperty("flat_deviation_rms", std::to_string(flat.deviation.rms));
  RecordProperty("loop_h_error_rms", std::to_string(smooth.mean_curvature_error.rms));
}

TEST(CompareMetrics, ReferencesGiveExactDistances) {
  auto sphere = make_sphere_reference({1, 0, 0}, 2.0);
  EXPECT_DOUBLE_EQ(sphere->deviation({1, 0, 5}), 3.0);
  EXPECT_DOUBLE_EQ(sphere->deviation({1, 0.5, 0}), 1.5);
  auto torus = make_torus_reference({0, 0, 1}, 2.0, 0.5);
  EXPECT_DOUBLE_EQ(torus->deviation({0, 0, 1}), 1.5);
  EXPECT_DOUBLE_EQ(torus->deviation({3, 0, 1}), 0.5);
  EXPECT_DOUBLE_EQ(torus->deviation({0, 2, 2}), 0.5);
  // Outer equator: (1/r + 1/(R + r)) / 2; inner: (1/r - 1/(R - r)) / 2.
  EXPECT_DOUBLE_EQ(torus->mean_curvature({2.5, 0, 1}), 0.5 * (2.0 + 1.0 / 2.5));
  EXPECT_DOUBLE_EQ(torus->mean_curvature({0, -1.5, 1}), 0.5 * (2.0 - 1.0 / 1.5));
  EXPECT_THROW(make_sphere_reference({0, 0, 0}, 0.0), InvalidArgument);
  EXPECT_THROW(make_torus_reference({0, 0, 0}, 1.0, 2.0), InvalidArgument);
}

TEST(CompareMetrics, CurvatureOfASphereSampleIsOneOverR) {
  // x(u, v) = r (cos u cos v, sin u cos v, sin v) at u = v = 0, normal outward.
  const double r = 2.5;
  SurfaceSample s;
  s.point = {r, 0, 0};
  s.normal = {1, 0, 0};
  s.du = {0, r, 0};
  s.dv = {0, 0, r};
  s.duu = {-r, 0, 0};
  s.duv = {0, 0, 0};
  s.dvv = {-r, 0, 0};
  s.has_second = true;
  const SampleCurvature c = curvature_of(s);
  ASSERT_TRUE(c.ok);
  EXPECT_DOUBLE_EQ(c.mean, 1.0 / r);
  EXPECT_DOUBLE_EQ(c.gauss, 1.0 / (r * r));
}

TEST(CompareMetrics, LatticeAndEdgeParameters) {
  EXPECT_EQ(lattice(4).size(), 15u);
  EXPECT_EQ(lattice_triangles(4).size(), 3u * 16u);
  double u, v;
  edge_parameter(0, 0.25, u, v);
  EXPECT_TRUE(u == 0.25 && v == 0.0);
  edge_parameter(1, 0.25, u, v);
  EXPECT_TRUE(u == 0.75 && v == 0.25);
  edge_parameter(2, 0.25, u, v);
  EXPECT_TRUE(u == 0.0 && v == 0.75);
  CompareSettings bad;
  bad.level = 0;
  EXPECT_THROW(compare_surfaces(octahedron(), {}, nullptr, bad, Progress(nullptr)), InvalidArgument);
}

TEST(CompareMetrics, CancelFlagStopsTheRun) {
  const Mesh m = octahedron();
  auto linear = make_linear_surface(m);
  isoform_progress sink{0.0f, 0, 1};
  EXPECT_THROW(compare_surfaces(m, {{"linear", linear.get()}}, nullptr, {}, Progress(&sink)), Cancelled);
}

}  // namespace
}  // namespace isoform::test

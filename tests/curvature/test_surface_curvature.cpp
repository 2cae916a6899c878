// Section 4.2: principal curvatures of triangulated surfaces against exact
// values: Table 4.1 beaten, convergence under refinement, contours of known
// shapes, and a defined result at every kind of bad vertex.
#include <gtest/gtest.h>

#include <cmath>

#include "../core/mesh_checks.h"
#include "libcore/curvature/surface_curvature.h"
#include "libcore/errors.h"
#include "libcore/mesh_normals.h"
#include "libcore/topology.h"
#include "truth.h"

using namespace isoform;
using namespace isoform::truth;

namespace {

void curvature(Mesh& m, CurvatureMethod method, int threads = 0) {
  CurvatureOptions o;
  o.method = method;
  o.threads = threads;
  compute_curvature(m, o, Progress(nullptr));
}

Rms shape_error(Shape s, int resolution, double jitter, CurvatureMethod method) {
  std::vector<Exact> exact;
  Mesh m = shape_mesh(s, resolution, jitter, 7, exact);
  estimate_normals(m);
  curvature(m, method);
  return rms_error(m, exact);
}

}  // namespace

// Table 4.1 with normals from the mesh alone, RMS over all 51 x 51 vertices:
// the default method at or below every entry of the seed's table. The bounds
// are what this implementation reached (docs/curvature-surface.md), with a
// margin for compilers; the plane is exact up to rounding.
TEST(SurfaceCurvature, Table41DefaultBeatsTheSeedAtEveryEntry) {
  // k1, k2, H, K as measured, times 1.5.
  const double reached[9][4] = {
      {1e-12, 1e-12, 1e-12, 1e-12},     {4.4e-5, 3.5e-6, 2.3e-5, 2.4e-6}, {5.6e-6, 6.6e-6, 4.8e-6, 4.8e-6},
      {1.2e-4, 3.9e-5, 7.5e-5, 8.0e-5}, {9.8e-5, 9.8e-5, 7.1e-5, 7.5e-5}, {5.7e-4, 5.7e-4, 4.4e-4, 6.2e-4},
      {2.3e-4, 2.3e-4, 1.8e-4, 1.8e-4}, {2.9e-5, 7.1e-5, 4.1e-5, 3.5e-5}, {1.8e-4, 6.5e-4, 3.6e-4, 4.4e-4}};
  const auto& graphs = table41_graphs();
  for (size_t g = 0; g < graphs.size(); ++g) {
    SCOPED_TRACE(graphs[g].name);
    const Table41Row row = table41_row(graphs[g], CurvatureOptions{}.method);
    const double got[4] = {row.all.k1, row.all.k2, row.all.mean, row.all.gauss};
    for (int q = 0; q < 4; ++q) {
      EXPECT_LE(got[q], std::max(graphs[g].seed_rms[q], 1e-12)) << "column " << q;
      EXPECT_LE(got[q], reached[g][q]) << "column " << q;
    }
  }
}

// The seed's own fit needs no more than the one-ring and the normal; on the
// osculating paraboloid z = (a x^2 + b y^2) / 2 with the exact normal it is
// exact at the apex, with isoform's sign (negative: the graph bends toward
// its upward normal).
TEST(SurfaceCurvature, SeedFitIsExactOnAParaboloidApex) {
  Graph g{"p", "", [](double x, double y) { return 0.5 * (0.8 * x * x + 0.3 * y * y); },
          [](double x, double y, double d[5]) { d[0] = 0.8 * x, d[1] = 0.3 * y, d[2] = 0.8, d[3] = 0, d[4] = 0.3; },
          {}};
  Mesh m = graph_mesh(g, 5);
  m.normals.assign(m.points.size(), 0.0f);
  for (size_t v = 0; v < m.vertex_count(); ++v) m.normals[3 * v + 2] = 1.0f;
  curvature(m, CurvatureMethod::Seed);
  const size_t apex = 2 * 5 + 2;
  // Exact up to the float the results are stored in.
  EXPECT_NEAR(m.curvature.k1[apex], -0.3, 1e-7);
  EXPECT_NEAR(m.curvature.k2[apex], -0.8, 1e-7);
  EXPECT_NEAR(m.curvature.mean[apex], -0.55, 1e-7);
  EXPECT_NEAR(m.curvature.gauss[apex], 0.24, 1e-7);
  EXPECT_NEAR(m.curvature.absolute[apex], 1.1, 1e-7);
  // k1 = -0.3 bends along y, k2 along x.
  EXPECT_NEAR(std::abs(m.curvature.d1[3 * apex + 1]), 1.0, 1e-9);
  EXPECT_NEAR(std::abs(m.curvature.d2[3 * apex + 0]), 1.0, 1e-9);
  EXPECT_EQ(m.curvature.flags[apex], 0);
}

// A valence-4 vertex whose neighbours lie on two lines makes the seed's 3x3
// system singular (no u v term is seen); the fit widens to the two-ring.
TEST(SurfaceCurvature, SingularOneRingWidens) {
  // A 5 x 5 grid of a sphere cap split so that the centre has valence 4.
  Mesh m;
  auto z = [](double x, double y) { return std::sqrt(4.0 - x * x - y * y); };
  for (int j = 0; j < 5; ++j)
    for (int i = 0; i < 5; ++i) {
      const double x = (i - 2) * 0.1, y = (j - 2) * 0.1;
      m.points.insert(m.points.end(), {float(x), float(y), float(z(x, y))});
      m.precise_points.insert(m.precise_points.end(), {x, y, z(x, y)});
    }
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 4; ++i) {
      const int32_t a = j * 5 + i, b = a + 1, c = a + 6, d = a + 5;
      // Diagonals point away from the centre in every quadrant.
      if ((i < 2) == (j < 2))
        m.triangles.insert(m.triangles.end(), {a, b, d, b, c, d});
      else
        m.triangles.insert(m.triangles.end(), {a, b, c, a, c, d});
    }
  estimate_normals(m);
  curvature(m, CurvatureMethod::Seed);
  const size_t centre = 12;
  EXPECT_TRUE(m.curvature.flags[centre] & kCurvatureWidened);
  EXPECT_NEAR(m.curvature.k1[centre], 0.5, 2e-3);
  EXPECT_NEAR(m.curvature.k2[centre], 0.5, 2e-3);
}

// The default method converges on closed surfaces, regular and jittered: the
// RMS of H and K falls by more than a factor 4 (second order) per doubling.
TEST(SurfaceCurvature, DefaultConvergesOnSphereTorusEllipsoid) {
  for (Shape s : {Shape::Sphere, Shape::Torus, Shape::Ellipsoid})
    for (double jitter : {0.0, 0.25}) {
      SCOPED_TRACE(std::string(shape_name(s)) + (jitter > 0 ? " jittered" : " regular"));
      const Rms a = shape_error(s, 32, jitter, CurvatureOptions{}.method);
      const Rms b = shape_error(s, 64, jitter, CurvatureOptions{}.method);
      EXPECT_LT(b.mean, a.mean / 4);
      EXPECT_LT(b.gauss, a.gauss / 4);
      EXPECT_LT(b.mean, 8e-3);
    }
}

// The seed's fit does not converge on jittered meshes with estimated normals
// (the reason the default absorbs normal error); it is kept, and says so.
TEST(SurfaceCurvature, SeedStallsOnJitteredMeshes) {
  const Rms a = shape_error(Shape::Sphere, 32, 0.25, CurvatureMethod::Seed);
  const Rms b = shape_error(Shape::Sphere, 64, 0.25, CurvatureMethod::Seed);
  EXPECT_GT(b.mean, a.mean / 2);
  EXPECT_GT(b.mean, 10 * shape_error(Shape::Sphere, 64, 0.25, CurvatureOptions{}.method).mean);
}

// On the torus, k1 = 1/r belongs to the tube's circles: d1 lies in the plane
// through the axis, perpendicular to the direction around the axis.
TEST(SurfaceCurvature, PrincipalDirectionsOnTheTorus) {
  std::vector<Exact> exact;
  Mesh m = shape_mesh(Shape::Torus, 64, 0.0, 1, exact);
  m.normals = shape_normals(Shape::Torus, m);
  curvature(m, CurvatureOptions{}.method);
  double worst = 0.0;
  for (size_t v = 0; v < m.vertex_count(); ++v) {
    const double x = m.points[3 * v], y = m.points[3 * v + 1], rho = std::hypot(x, y);
    const double around = (-y * m.curvature.d1[3 * v] + x * m.curvature.d1[3 * v + 1]) / rho;
    worst = std::max(worst, std::abs(around));
    EXPECT_NEAR(m.curvature.k1[v], 2.5, 0.02);
  }
  EXPECT_LT(worst, 2e-2);
}

TEST(SurfaceCurvature, SameBitsForAnyThreadCount) {
  std::vector<Exact> exact;
  Mesh a = shape_mesh(Shape::Ellipsoid, 64, 0.25, 3, exact);
  estimate_normals(a);
  Mesh b = a;
  curvature(a, CurvatureOptions{}.method, 1);
  curvature(b, CurvatureOptions{}.method, 2);
  EXPECT_EQ(a.curvature.k1, b.curvature.k1);
  EXPECT_EQ(a.curvature.k2, b.curvature.k2);
  EXPECT_EQ(a.curvature.d1, b.curvature.d1);
  EXPECT_EQ(a.curvature.flags, b.curvature.flags);
}

TEST(SurfaceCurvature, CancelLeavesTheMeshAlone) {
  std::vector<Exact> exact;
  Mesh m = shape_mesh(Shape::Sphere, 32, 0.0, 1, exact);
  estimate_normals(m);
  isoform_progress sink{};
  sink.cancel = 1;
  EXPECT_THROW(compute_curvature(m, CurvatureOptions{}, Progress(&sink)), Cancelled);
  EXPECT_TRUE(m.curvature.empty());
}

// Bad vertices get a defined, finite result and a flag: an isolated vertex,
// a non-manifold edge (three triangles), a duplicate point, and a mesh
// without triangles.
TEST(SurfaceCurvature, BadVerticesAreFlaggedNeverNaN) {
  std::vector<Exact> exact;
  Mesh m = shape_mesh(Shape::Sphere, 16, 0.0, 1, exact);
  const int32_t n = int32_t(m.vertex_count());
  // An isolated vertex.
  m.points.insert(m.points.end(), {5.0f, 5.0f, 5.0f});
  // A fin on edge (0, 1): a third triangle there, to a new point.
  m.points.insert(m.points.end(), {0.0f, 0.0f, 0.0f});
  m.triangles.insert(m.triangles.end(), {m.triangles[0], m.triangles[1], n + 1});
  // A duplicate of vertex 2, unused.
  m.points.insert(m.points.end(), {m.points[6], m.points[7], m.points[8]});
  compute_topology(m);
  estimate_normals(m);
  curvature(m, CurvatureOptions{}.method);
  for (size_t v = 0; v < m.vertex_count(); ++v) {
    SCOPED_TRACE(v);
    for (const auto* a : {&m.curvature.k1, &m.curvature.k2, &m.curvature.mean, &m.curvature.gauss})
      EXPECT_TRUE(std::isfinite((*a)[v]));
    for (int c = 0; c < 3; ++c) EXPECT_TRUE(std::isfinite(m.curvature.d1[3 * v + size_t(c)]));
  }
  EXPECT_TRUE(m.curvature.flags[size_t(n)] & kCurvatureIsolated);
  EXPECT_EQ(m.curvature.k1[size_t(n)], 0.0f);
  EXPECT_TRUE(m.curvature.flags[size_t(m.triangles[0])] & kCurvatureNonmanifold);
  EXPECT_EQ(m.curvature.stats.isolated, 2);  // the lone point and the unused duplicate
  EXPECT_GE(m.curvature.stats.nonmanifold, 2);

  Mesh empty;
  empty.points = {0, 0, 0, 1, 0, 0};
  curvature(empty, CurvatureOptions{}.method);
  EXPECT_EQ(empty.curvature.stats.isolated, 2);
}

// A triangle without a plane is refused, naming it, as the reduction refuses
// it: one that repeats a vertex, one of three points on a line, and the
// fuzzer's kind of case, subnormal coordinates beside (1, 0, 0), here on one
// line. A coordinate that is not finite is refused too.
TEST(SurfaceCurvature, TrianglesWithoutAPlaneAreRefused) {
  struct Case {
    std::vector<float> points;
    std::vector<int32_t> triangles;
    std::string message;
  } cases[] = {
      {{0, 0, 0, 1, 0, 0, 0, 1, 0}, {0, 1, 2, 0, 2, 2}, "curvature: triangle 1 uses a vertex twice (0, 2, 2)"},
      {{0, 0, 0, 1, 0, 0, 0, 1, 0, 2, 0, 0}, {0, 1, 2, 0, 3, 1},
       "curvature: triangle 1 (0, 3, 1) has no area at the precision of its coordinates"},
      {{1e-45f, 0, 0, 1, 0, 0, 3e-45f, 0, 0, 0, 1e-33f, 0}, {0, 1, 3, 0, 1, 2},
       "curvature: triangle 1 (0, 1, 2) has no area at the precision of its coordinates"},
      {{0, 0, 0, 1, 0, 0, 0, NAN, 0}, {0, 1, 2}, "curvature: vertex 2 has a coordinate that is not finite"},
  };
  for (Case& c : cases) {
    Mesh m;
    m.points = c.points;
    m.triangles = c.triangles;
    try {
      curvature(m, CurvatureOptions{}.method);
      ADD_FAILURE() << "accepted: " << c.message;
    } catch (const InvalidArgument& e) {
      EXPECT_EQ(std::string(e.what()).rfind(c.message, 0), 0u) << e.what();
    }
    EXPECT_TRUE(m.curvature.empty());
  }
}

// Contours of a level-set sphere and torus (Chapter 3, Zucker-Hummel
// normals): H near 1/r and K near 1/r^2 on the sphere; on the torus the tube
// curvature near 1/r. The tolerances are what these meshes give.
TEST(SurfaceCurvature, ContoursOfSphereAndTorus) {
  const double r = 12.0;
  auto sphere = test::dense_grid({32, 32, 32}, [&](int x, int y, int z) {
    return std::sqrt((x - 15.5) * (x - 15.5) + (y - 15.3) * (y - 15.3) + (z - 15.7) * (z - 15.7)) - r;
  }, GridClass::LevelSet);
  Mesh s = test::run_contour(*sphere, 0.0);
  curvature(s, CurvatureOptions{}.method);
  double h2 = 0, k2 = 0;
  for (size_t v = 0; v < s.vertex_count(); ++v) {
    h2 += std::pow(s.curvature.mean[v] - 1 / r, 2);
    k2 += std::pow(s.curvature.gauss[v] - 1 / (r * r), 2);
  }
  const double h_rms = std::sqrt(h2 / double(s.vertex_count())), k_rms = std::sqrt(k2 / double(s.vertex_count()));
  EXPECT_LT(h_rms, 0.05 / r);
  EXPECT_LT(k_rms, 0.1 / (r * r));

  const double R = 14.0, rt = 6.0;
  auto torus = test::dense_grid({48, 48, 24}, [&](int x, int y, int z) {
    const double q = std::hypot(x - 23.5, y - 23.5) - R;
    return std::sqrt(q * q + (z - 11.5) * (z - 11.5)) - rt;
  }, GridClass::LevelSet);
  Mesh t = test::run_contour(*torus, 0.0);
  curvature(t, CurvatureOptions{}.method);
  double t2 = 0;
  for (size_t v = 0; v < t.vertex_count(); ++v) t2 += std::pow(t.curvature.k1[v] - 1 / rt, 2);
  EXPECT_LT(std::sqrt(t2 / double(t.vertex_count())), 0.05 / rt);
  std::printf("contour sphere r=%g: RMS H %.3g (%.2f%% of 1/r), K %.3g; torus tube RMS k1 %.3g\n", r, h_rms,
              100 * h_rms * r, k_rms, std::sqrt(t2 / double(t.vertex_count())));
}

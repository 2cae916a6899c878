// Curvature of trivariate graphs (Hamann 1991, Section 4.3) on analytic
// inputs: the platelet, the frame, the eigenvalues, closed forms, invariance
// under the grid's transform, sparse data and determinism.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <cstring>
#include <memory>
#include <set>

#include "libcore/curvature/graph_block.h"
#include "libcore/curvature/graph_frame.h"
#include "libcore/curvature/graph_platelet.h"
#include "libcore/curvature/graph_point.h"
#include "libcore/curvature/graph_volume.h"
#include "libcore/volume.h"

namespace isoform {
namespace {

using Offset = std::array<int, 3>;

TEST(GraphPlatelet, IsTheVertexStarOfTheSixTetrahedraSplit) {
  // By hand from tetra.h: axis neighbours, the face diagonals (p=1,q=0) to
  // (p=0,q=1) and the cell diagonal (1,0,0) to (0,1,1), both ways.
  const std::set<Offset> expected = {{1, 0, 0},  {-1, 0, 0}, {0, 1, 0},  {0, -1, 0}, {0, 0, 1},
                                     {0, 0, -1}, {-1, 1, 0}, {1, -1, 0}, {-1, 0, 1}, {1, 0, -1},
                                     {0, -1, 1}, {0, 1, -1}, {-1, 1, 1}, {1, -1, -1}};
  const auto& offsets = graph_platelet_offsets();
  EXPECT_EQ(offsets.size(), 14u);
  EXPECT_EQ(std::set<Offset>(offsets.begin(), offsets.end()), expected);
}

TEST(GraphFrame, GramSchmidtGivesAnOrthonormalBasisWithTheNormal) {
  const GraphFrame f = graph_frame({0.3, -1.2, 2.5});
  const double l = std::sqrt(1 + 0.09 + 1.44 + 6.25);
  EXPECT_NEAR(f.n[0], -0.3 / l, 1e-15);
  EXPECT_NEAR(f.n[3], 1 / l, 1e-15);
  std::array<Vec4d, 4> all = {f.n, f.b[0], f.b[1], f.b[2]};
  for (int a = 0; a < 4; ++a)
    for (int b = 0; b < 4; ++b) {
      double d = 0;
      for (int c = 0; c < 4; ++c) d += all[a][c] * all[b][c];
      EXPECT_NEAR(d, a == b ? 1.0 : 0.0, 1e-14) << a << " " << b;
    }
}

TEST(GraphPrincipal, FromDerivativesMatchesTheNonSymmetricMatrixOf436) {
  const std::array<double, 3> g = {0.7, -0.4, 1.1};
  const Sym3 h = {{{0.9, 0.3, -0.2}, {0.3, -0.5, 0.6}, {-0.2, 0.6, 0.1}}};
  Eigen::Matrix3d hm, gm;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      hm(i, j) = h[i][j];
      gm(i, j) = (i == j) + g[i] * g[j];
    }
  const double l = std::sqrt(1 + 0.49 + 0.16 + 1.21);
  const Eigen::Matrix3d minus_a = hm * gm.inverse() / l;
  Eigen::EigenSolver<Eigen::Matrix3d> general(minus_a);
  std::array<double, 3> e;
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(general.eigenvalues()[i].imag(), 0.0, 1e-12);
    e[i] = general.eigenvalues()[i].real();
  }
  std::sort(e.begin(), e.end());
  const GraphPrincipal p = graph_principal_from_derivatives(g, h);
  EXPECT_NEAR(p.k1, e[2], 1e-13);
  EXPECT_NEAR(p.k2, e[1], 1e-13);
  EXPECT_NEAR(p.k3, e[0], 1e-13);
  EXPECT_NEAR(p.mean, (e[0] + e[1] + e[2]) / 3, 1e-13);
  EXPECT_NEAR(p.gauss, e[0] * e[1] * e[2], 1e-13);
}

// f(x) = 1/2 x^T Q x + b.x sampled on a grid around the origin, world
// spacing h; the origin is grid point (n/2, n/2, n/2).
struct Quadratic {
  double q[3][3];
  double b[3];
  double operator()(const Vec3d& x) const {
    double v = 0;
    for (int i = 0; i < 3; ++i) {
      v += b[i] * x[i];
      for (int j = 0; j < 3; ++j) v += 0.5 * q[i][j] * x[i] * x[j];
    }
    return v;
  }
};

// Q = R diag(0.8, 0.2, -0.3) R^T with R a rotation: at the origin with b = 0
// the principal curvatures are exactly 0.8, 0.2, -0.3.
Quadratic rotated_quadratic(const double b[3]) {
  const Eigen::Matrix3d r = (Eigen::AngleAxisd(0.4, Eigen::Vector3d::UnitZ()) *
                             Eigen::AngleAxisd(-0.7, Eigen::Vector3d(1, 1, 0).normalized()))
                                .toRotationMatrix();
  const Eigen::Matrix3d q = r * Eigen::Vector3d(0.8, 0.2, -0.3).asDiagonal() * r.transpose();
  Quadratic f;
  for (int i = 0; i < 3; ++i) {
    f.b[i] = b[i];
    for (int j = 0; j < 3; ++j) f.q[i][j] = q(i, j);
  }
  return f;
}

GraphCurvature at_origin(const Quadratic& f, const Affine& map, GraphMethod method) {
  constexpr int n = 13;
  GraphBlock block;
  block.reset({0, 0, 0}, {n, n, n});
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) block.set({i, j, k}, f(map.apply({double(i), double(j), double(k)})));
  return graph_curvature_at(block.samples({n / 2, n / 2, n / 2}), GraphAxes::of(map), method);
}

TEST(GraphCurvature, QuadraticAtTheOriginHasTheHessiansEigenvalues) {
  const double zero[3] = {0, 0, 0};
  const Quadratic f = rotated_quadratic(zero);
  const Affine map = Affine::scale_translate({0.1, 0.1, 0.1}, {-0.6, -0.6, -0.6});
  const GraphCurvature d = at_origin(f, map, GraphMethod::Default);
  EXPECT_EQ(d.fit, GraphFit::JetCentred);
  // The default fit reproduces quadratics: exact to rounding.
  EXPECT_NEAR(d.curvature.k1, 0.8, 1e-11);
  EXPECT_NEAR(d.curvature.k2, 0.2, 1e-11);
  EXPECT_NEAR(d.curvature.k3, -0.3, 1e-11);
  EXPECT_NEAR(d.curvature.mean, 0.7 / 3, 1e-11);
  EXPECT_NEAR(d.curvature.gauss, 0.8 * 0.2 * -0.3, 1e-11);
  // The seed's fit in the tangent frame: the graph is not a quadric there,
  // but at a point of zero gradient with a symmetric platelet only the
  // quartic terms of the tangent-frame expansion bias it, O(h^2).
  const GraphCurvature s = at_origin(f, map, GraphMethod::Seed);
  EXPECT_EQ(s.fit, GraphFit::Platelet);
  EXPECT_NEAR(s.curvature.k1, 0.8, 2e-2);
  EXPECT_NEAR(s.curvature.k2, 0.2, 2e-2);
  EXPECT_NEAR(s.curvature.k3, -0.3, 2e-2);
}

TEST(GraphCurvature, QuadraticWithSlopeMatches436InClosedForm) {
  const double b[3] = {0.5, -0.3, 0.8};
  const Quadratic f = rotated_quadratic(b);
  const Affine map = Affine::scale_translate({0.05, 0.05, 0.05}, {-0.3, -0.3, -0.3});
  const Sym3 q = {{{f.q[0][0], f.q[0][1], f.q[0][2]}, {f.q[1][0], f.q[1][1], f.q[1][2]}, {f.q[2][0], f.q[2][1], f.q[2][2]}}};
  const GraphPrincipal exact = graph_principal_from_derivatives({b[0], b[1], b[2]}, q);
  const GraphCurvature d = at_origin(f, map, GraphMethod::Default);
  EXPECT_NEAR(d.curvature.k1, exact.k1, 1e-10);
  EXPECT_NEAR(d.curvature.k2, exact.k2, 1e-10);
  EXPECT_NEAR(d.curvature.k3, exact.k3, 1e-10);
  const GraphCurvature s = at_origin(f, map, GraphMethod::Seed);
  EXPECT_NEAR(s.curvature.mean, exact.mean, 1e-2);
}

TEST(GraphCurvature, RotatingAndMovingTheGridChangesNothing) {
  const double b[3] = {0.2, 0.1, -0.4};
  const Quadratic f = rotated_quadratic(b);
  const Affine plain = Affine::scale_translate({0.1, 0.1, 0.1}, {-0.6, -0.6, -0.6});
  // The same samples under a rotated and moved transform: the world function
  // is f composed with a rigid motion, whose graph has the same curvatures.
  const Eigen::Matrix3d r = Eigen::AngleAxisd(1.1, Eigen::Vector3d(1, -2, 0.5).normalized()).toRotationMatrix();
  Affine moved;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) moved.m[i][j] = 0.1 * r(i, j);
    moved.m[i][3] = 3.0 + i;
  }
  constexpr int n = 13;
  GraphBlock block;
  block.reset({0, 0, 0}, {n, n, n});
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) block.set({i, j, k}, f(plain.apply({double(i), double(j), double(k)})));
  for (GraphMethod method : {GraphMethod::Default, GraphMethod::Seed})
    for (const Index3 p : {Index3{6, 6, 6}, Index3{0, 3, 12}, Index3{2, 11, 5}}) {
      const GraphCurvature a = graph_curvature_at(block.samples(p), GraphAxes::of(plain), method);
      const GraphCurvature c = graph_curvature_at(block.samples(p), GraphAxes::of(moved), method);
      EXPECT_EQ(a.fit, c.fit);
      EXPECT_NEAR(a.curvature.k1, c.curvature.k1, 1e-9);
      EXPECT_NEAR(a.curvature.k2, c.curvature.k2, 1e-9);
      EXPECT_NEAR(a.curvature.k3, c.curvature.k3, 1e-9);
    }
}

// A dense float volume of f on an n^3 grid, as the C API would make it.
std::shared_ptr<const ScalarGrid> dense_grid(int n, double h, double (*f)(double, double, double)) {
  std::vector<float> v(size_t(n) * n * n);
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) v[(size_t(k) * n + j) * n + i] = float(f(i * h, j * h, k * h));
  DenseVolume volume("f", GridClass::Other, std::move(v), {n, n, n}, Affine::scale_translate({h, h, h}, {0, 0, 0}));
  return volume.load(0);
}

double wave(double x, double y, double z) { return 0.3 * std::sin(2 * x) * std::cos(y) + 0.2 * z * z * x; }

TEST(GraphVolume, SameBitsForAnyThreadCountAndSeamlessBricks) {
  // 37 samples: bricks of 16 make seams at 16 and 32 and a short last brick.
  const auto grid = dense_grid(37, 0.05, wave);
  std::vector<std::vector<float>> runs;
  for (int threads : {1, 2, 0}) {
    GraphVolumeOptions o;
    o.threads = threads;
    const auto result = graph_curvature_volume(*grid, "", o, Progress(nullptr));
    EXPECT_EQ(result->stats().points, 37LL * 37 * 37);
    std::vector<float> all;
    Brick brick;
    for (int g = 0; g < kGraphGrids; ++g) {
      const auto r = result->load(g);
      for (size_t b = 0; b < r->bricks->brick_count(); ++b) {
        r->bricks->fill(b, brick);
        all.insert(all.end(), brick.samples.begin(), brick.samples.end());
      }
    }
    runs.push_back(all);
    // A point beside a seam reads across it: its box is centred.
    EXPECT_EQ(result->stats().fits[size_t(GraphFit::JetCentred)], 31LL * 31 * 31);
  }
  ASSERT_EQ(runs[0].size(), runs[1].size());
  EXPECT_EQ(std::memcmp(runs[0].data(), runs[1].data(), runs[0].size() * sizeof(float)), 0);
  EXPECT_EQ(std::memcmp(runs[0].data(), runs[2].data(), runs[0].size() * sizeof(float)), 0);
}

// A brick source of one 8^3 brick whose defined flags mark a ball: results
// must appear exactly there.
class BallBricks : public BrickSource {
 public:
  size_t brick_count() const override { return 1; }
  void fill(size_t, Brick& out) const override {
    out.resize({0, 0, 0}, {8, 8, 8}, true);
    for (int k = -1; k <= 9; ++k)
      for (int j = -1; j <= 9; ++j)
        for (int i = -1; i <= 9; ++i) {
          out.samples[out.at(i, j, k)] = float(0.1 * (i * i + j * j) - 0.05 * k);
          out.defined[out.at(i, j, k)] = inside(i, j, k);
        }
  }
  static bool inside(int i, int j, int k) { return (i - 4) * (i - 4) + (j - 4) * (j - 4) + (k - 4) * (k - 4) <= 12; }
};

TEST(GraphVolume, ResultsOnlyAtDefinedSamplesUsingDefinedNeighbours) {
  ScalarGrid grid;
  grid.index_to_world = Affine::scale_translate({0.5, 0.5, 0.5}, {0, 0, 0});
  grid.bricks = std::make_shared<BallBricks>();
  const auto result = graph_curvature_volume(grid, "", GraphVolumeOptions{}, Progress(nullptr));
  long long inside = 0;
  for (int k = 0; k < 8; ++k)
    for (int j = 0; j < 8; ++j)
      for (int i = 0; i < 8; ++i) inside += BallBricks::inside(i, j, k);
  EXPECT_EQ(result->stats().points, inside);
  EXPECT_EQ(result->facts(0).active_voxels, inside);
  Brick brick;
  result->load(2)->bricks->fill(0, brick);
  // f = 0.1 (i^2 + j^2) - 0.05 k in index units; world spacing 0.5, so
  // f = 0.4 (x^2 + y^2) - 0.1 z: a paraboloid, polynomial of degree 2, which
  // every jet fit on the ball reproduces. At the centre, world (2, 2, 2),
  // the gradient is (1.6, 1.6, -0.1): compare with 4.36.
  const Sym3 hess = {{{0.8, 0, 0}, {0, 0.8, 0}, {0, 0, 0}}};
  const GraphPrincipal exact = graph_principal_from_derivatives({1.6, 1.6, -0.1}, hess);
  EXPECT_NEAR(brick.value(4, 4, 4), exact.k1, 1e-5);
  for (int k = -1; k <= 9; ++k)
    for (int j = -1; j <= 9; ++j)
      for (int i = -1; i <= 9; ++i) {
        const bool own = i >= 0 && j >= 0 && k >= 0 && i < 8 && j < 8 && k < 8;
        EXPECT_EQ(brick.is_defined(i, j, k), own && BallBricks::inside(i, j, k)) << i << " " << j << " " << k;
      }
}

double linear_f(double x, double y, double z) { return 0.2 * (x + y + z); }

TEST(GraphVolume, LinearFunctionHasZeroCurvatureFromFloatSamples) {
  const auto grid = dense_grid(20, 0.1, linear_f);
  for (GraphMethod method : {GraphMethod::Default, GraphMethod::Seed}) {
    GraphVolumeOptions o;
    o.method = method;
    const auto result = graph_curvature_volume(*grid, "", o, Progress(nullptr));
    for (int g = 0; g < kGraphGrids; ++g) {
      // Float samples carry rounding of 1e-8 relative; it reaches the
      // curvature divided by h^2.
      EXPECT_LT(std::abs(result->facts(g).value_min), 1e-4);
      EXPECT_LT(std::abs(result->facts(g).value_max), 1e-4);
    }
  }
}

}  // namespace
}  // namespace isoform

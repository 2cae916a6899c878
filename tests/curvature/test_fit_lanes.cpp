// The side-by-side fits (fit_height_lanes, fit_vertices) against the one-at-
// a-time ones (fit_height, fit_vertex): the same bits for every lane, on
// ordinary, degenerate and too small point sets, and on whole meshes with
// boundaries, widened and lowered vertices.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <random>
#include <vector>

#include "libcore/curvature/height_fit.h"
#include "libcore/curvature/vertex_fit.h"
#include "libcore/mesh_normals.h"
#include "truth.h"

using namespace isoform;

namespace {

struct PointSet {
  std::vector<double> u, v, d;
  int count() const { return int(u.size()); }
};

// Rings of points around the origin on a quartic height field; kind 1 puts
// them on a line (a singular system), kind 2 keeps only a few, kind 3 none,
// kind 4 gives one point a height that is not a number (a solution that is
// not finite from a well-conditioned system).
PointSet point_set(std::mt19937& rng, int kind) {
  std::uniform_real_distribution<double> jitter(-0.3, 0.3);
  PointSet p;
  const int n = kind == 2 ? 2 + int(rng() % 12) : kind == 3 ? 0 : 20 + int(rng() % 30);
  for (int j = 0; j < n; ++j) {
    const double r = 0.01 * (1 + j / 6), a = j * 1.047 + jitter(rng);
    const double x = r * std::cos(a), y = kind == 1 ? 0.5 * x : r * std::sin(a);
    p.u.push_back(x);
    p.v.push_back(y);
    p.d.push_back(0.3 * x * x + 0.1 * x * y - 0.2 * y * y + x * x * x + 0.5 * x * x * y * y + 0.01 * x);
  }
  if (kind == 4) p.d[3] = std::nan("");
  return p;
}

bool same_bits(const HeightFit& a, const HeightFit& b) {
  return a.ok == b.ok && std::memcmp(&a.fu, &b.fu, 5 * sizeof(double)) == 0 &&
         std::memcmp(&a.rcond, &b.rcond, sizeof(double)) == 0;
}

void expect_same(const VertexFitResult& a, const VertexFitResult& b, size_t v) {
  EXPECT_EQ(a.flags, b.flags) << "vertex " << v;
  const PrincipalCurvatures &p = a.curvature, &q = b.curvature;
  EXPECT_EQ(std::memcmp(&p.k1, &q.k1, sizeof(double)), 0) << "vertex " << v;
  EXPECT_EQ(std::memcmp(&p.k2, &q.k2, sizeof(double)), 0) << "vertex " << v;
  EXPECT_EQ(std::memcmp(p.d1.data(), q.d1.data(), 3 * sizeof(double)), 0) << "vertex " << v;
  EXPECT_EQ(std::memcmp(p.normal.data(), q.normal.data(), 3 * sizeof(double)), 0) << "vertex " << v;
}

}  // namespace

TEST(FitLanes, SameBitsAsOneAtATime) {
  std::mt19937 rng(5);
  for (FitModel model : {FitModel::SeedQuadratic, FitModel::Quadric, FitModel::Cubic, FitModel::Quartic}) {
    int fitted = 0, refused = 0;
    for (int round = 0; round < 200; ++round) {
      const int lanes = 1 + round % 4;
      PointSet sets[4];
      for (int l = 0; l < lanes; ++l)
        sets[l] = point_set(rng, round % 7 == l ? 1 + round % 3 : round % 11 == l ? 4 : 0);
      // Side by side: point j of set l at 4 j + l, zeros beyond a set's end.
      int count[4] = {0, 0, 0, 0}, most = 0;
      for (int l = 0; l < lanes; ++l) most = std::max(most, count[l] = sets[l].count());
      std::vector<double> u(4 * size_t(most), 0.0), v(u), d(u);
      for (int l = 0; l < lanes; ++l)
        for (int j = 0; j < count[l]; ++j) {
          u[4 * size_t(j) + size_t(l)] = sets[l].u[size_t(j)];
          v[4 * size_t(j) + size_t(l)] = sets[l].v[size_t(j)];
          d[4 * size_t(j) + size_t(l)] = sets[l].d[size_t(j)];
        }
      HeightFit out[4];
      fit_height_lanes(model, u.data(), v.data(), d.data(), count, out);
      for (int l = 0; l < lanes; ++l) {
        const HeightFit one = fit_height(model, sets[l].u.data(), sets[l].v.data(), sets[l].d.data(), count[l]);
        EXPECT_TRUE(same_bits(one, out[l])) << "model " << int(model) << " round " << round << " lane " << l;
        (one.ok ? fitted : refused) += 1;
      }
    }
    // Both outcomes were exercised.
    EXPECT_GT(fitted, 300) << "model " << int(model);
    EXPECT_GT(refused, 20) << "model " << int(model);
  }
}

// Two groups of four side by side (eight lanes with AVX-512): each lane as
// its set alone, with the groups' sets of different lengths, every set
// padded to the longest of all eight.
TEST(FitLanes, TwoGroupsSameBitsAsOneAtATime) {
  std::mt19937 rng(9);
  for (FitModel model : {FitModel::SeedQuadratic, FitModel::Quadric, FitModel::Cubic, FitModel::Quartic}) {
    int fitted = 0, refused = 0;
    for (int round = 0; round < 120; ++round) {
      const int lanes = 5 + round % 4;  // the second group partly used
      PointSet sets[8];
      for (int l = 0; l < lanes; ++l)
        sets[l] = point_set(rng, round % 9 == l ? 1 + round % 3 : round % 13 == l ? 4 : 0);
      int most = 0;
      for (int l = 0; l < lanes; ++l) most = std::max(most, sets[l].count());
      std::vector<double> data[2][3];
      LaneGroup groups[2];
      for (int g = 0; g < 2; ++g) {
        for (auto& a : data[g]) a.assign(4 * size_t(most), 0.0);
        for (int k = 0; k < 4; ++k) {
          const PointSet& p = sets[4 * g + k];
          groups[g].count[k] = p.count();
          for (int j = 0; j < p.count(); ++j) {
            data[g][0][4 * size_t(j) + size_t(k)] = p.u[size_t(j)];
            data[g][1][4 * size_t(j) + size_t(k)] = p.v[size_t(j)];
            data[g][2][4 * size_t(j) + size_t(k)] = p.d[size_t(j)];
          }
        }
        groups[g].u = data[g][0].data();
        groups[g].v = data[g][1].data();
        groups[g].d = data[g][2].data();
      }
      HeightFit out[2][4];
      fit_height_lanes(model, groups, out);
      for (int l = 0; l < 8; ++l) {
        const PointSet& p = sets[l];
        const HeightFit one = fit_height(model, p.u.data(), p.v.data(), p.d.data(), p.count());
        EXPECT_TRUE(same_bits(one, out[l / 4][l % 4])) << "model " << int(model) << " round " << round << " lane " << l;
        if (l < lanes) (one.ok ? fitted : refused) += 1;
      }
    }
    EXPECT_GT(fitted, 300) << "model " << int(model);
    EXPECT_GT(refused, 20) << "model " << int(model);
  }
}

TEST(FitLanes, VerticesInGroupsMatchFitVertex) {
  std::vector<truth::Exact> exact;
  Mesh closed = truth::shape_mesh(truth::Shape::Ellipsoid, 40, 0.25, 3, exact);
  estimate_normals(closed);
  Mesh open = truth::graph_mesh(truth::table41_graphs()[4], 21);
  estimate_normals(open);
  for (const Mesh* m : {&closed, &open}) {
    const VertexRings rings(*m);
    for (CurvatureMethod method :
         {CurvatureMethod::Seed, CurvatureMethod::Quadric, CurvatureMethod::Cubic, CurvatureMethod::Quartic})
      for (int extra : {0, 1}) {
        VertexFitScratch a, b;
        const int32_t n = int32_t(m->vertex_count());
        // Groups of 3, 4, 5, 7 and 8 (one group of lanes and two), not aligned.
        const int sizes[] = {3, 4, 5, 7, 8};
        for (int32_t first = 0, k = 0; first < n; ++k) {
          const int count = std::min<int32_t>(sizes[k % 5], n - first);
          VertexFitResult group[8];
          fit_vertices(*m, rings, first, count, method, extra, a, group);
          for (int i = 0; i < count; ++i)
            expect_same(fit_vertex(*m, rings, first + i, method, extra, b), group[i], size_t(first + i));
          first += count;
        }
      }
  }
}

// Section 2.2, domain subdivision: x_r and dx for given q and alpha (worked
// by hand below), the mesh's corners, colours and orientation, the
// spherical domain of Figure 2.4, and bad settings.
#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "libcore/errors.h"
#include "libcore/visualize/boxes.h"
#include "visualize_support.h"

namespace isoform::visualize {
namespace {

using test::make_grid;

// Figure 2.2: [0, 39], q = 5, alpha = 1: dx = 39 / (5 + 1 * 4) = 39 / 9,
// x_r = r (1 + 1) 39 / 9 = 0, 78/9, 156/9, 234/9, 312/9; the last ends at 39.
TEST(Subdivision, Figure22Corners) {
  const SubdivisionAxis a{0.0, 39.0, 1.0, 5};
  EXPECT_DOUBLE_EQ(a.delta(), 39.0 / 9.0);
  const double expected[5] = {0.0, 78.0 / 9.0, 156.0 / 9.0, 26.0, 312.0 / 9.0};
  for (int r = 0; r < 5; ++r) EXPECT_NEAR(a.start(r), expected[r], 1e-12);
  EXPECT_NEAR(a.start(4) + a.delta(), 39.0, 1e-12);
}

// Figure 2.3: q = 8, alpha = 2: dx = 39 / (8 + 2 * 7) = 39 / 22, x_r = 3 r 39 / 22.
TEST(Subdivision, Figure23Corners) {
  const SubdivisionAxis a{0.0, 39.0, 2.0, 8};
  EXPECT_DOUBLE_EQ(a.delta(), 39.0 / 22.0);
  EXPECT_NEAR(a.start(1), 117.0 / 22.0, 1e-12);
  EXPECT_NEAR(a.start(7), 819.0 / 22.0, 1e-12);
  EXPECT_NEAR(a.start(7) + a.delta(), 39.0, 1e-12);
  // q = 1 is the whole interval whatever the gap.
  EXPECT_DOUBLE_EQ((SubdivisionAxis{2.0, 6.0, 3.0, 1}).delta(), 4.0);
}

TEST(Boxes, MeshCornersAreTheSubdivisionCornersInWorld) {
  // 40^3 samples at spacing 0.5 from -1: world x = -1 + i / 2, so [-1, 18.5].
  const auto g = make_grid({40, 40, 40}, [](int i, int, int) { return double(i); }, {0.5, 0.5, 0.5}, {-1, -1, -1});
  BoxSettings s;
  s.q = {5, 3, 2};
  s.gap = {1.0, 0.5, 2.0};
  const Mesh m = domain_boxes(*g.grid, g.domain, box_map(g.domain), s, ColourSettings{});
  EXPECT_EQ(m.vertex_count(), 30u * 6 * 4);
  EXPECT_EQ(m.triangle_count(), 30u * 6 * 2);
  EXPECT_EQ(m.parts.size(), m.triangle_count());
  for (int a = 0; a < 3; ++a) {
    std::set<long> seen;
    for (size_t v = 0; v < m.vertex_count(); ++v) seen.insert(std::lround(m.points[3 * v + a] * 1e4));
    const SubdivisionAxis axis{0.0, 39.0, s.gap[a], s.q[a]};
    std::set<long> expected;
    for (int r = 0; r < s.q[a]; ++r) {
      expected.insert(std::lround((-1 + 0.5 * axis.start(r)) * 1e4));
      expected.insert(std::lround((-1 + 0.5 * (axis.start(r) + axis.delta())) * 1e4));
    }
    EXPECT_EQ(seen, expected) << "axis " << a;
  }
}

TEST(Boxes, ColoursFollowTheCornerValuesAndNormalsPointOut) {
  // f = x on [0, 39]: corner values 0 .. 39 map green .. white.
  const auto g = make_grid({40, 40, 40}, [](int i, int, int) { return double(i); });
  BoxSettings s;
  ColourSettings c;
  c.map = MapId::GreenWhite;
  const Mesh m = domain_boxes(*g.grid, g.domain, box_map(g.domain), s, c);
  for (size_t v = 0; v < m.vertex_count(); ++v) {
    const float x = m.points[3 * v];
    if (x == 0.0f) {
      EXPECT_EQ((std::array<uint8_t, 3>{m.colors[4 * v], m.colors[4 * v + 1], m.colors[4 * v + 2]}),
                (Rgb{0, 128, 0}));
    }
    if (std::fabs(x - 39.0f) < 1e-4f) {
      EXPECT_EQ(m.colors[4 * v], 255);
    }
    EXPECT_EQ(m.colors[4 * v + 3], 255);
  }
  // Box 0's -x face: its normals are -x, its triangles wind outward.
  for (size_t v = 0; v < 4; ++v) EXPECT_FLOAT_EQ(m.normals[3 * v], -1.0f);
  const int32_t* t = &m.triangles[0];
  const float* p0 = &m.points[3 * t[0]];
  const float* p1 = &m.points[3 * t[1]];
  const float* p2 = &m.points[3 * t[2]];
  const double nx = (p1[1] - p0[1]) * (p2[2] - p0[2]) - (p1[2] - p0[2]) * (p2[1] - p0[1]);
  EXPECT_LT(nx, 0.0);
}

TEST(Boxes, FacePointsAndCentroidLines) {
  const auto g = make_grid({10, 10, 10}, [](int i, int j, int k) { return double(i + j + k); });
  BoxSettings s;
  s.q = {2, 2, 2};
  s.face_cells = {3, 2};
  s.centroid_lines = true;
  const Mesh m = domain_boxes(*g.grid, g.domain, box_map(g.domain), s, ColourSettings{});
  EXPECT_EQ(m.triangle_count(), 8u * 6 * 3 * 2 * 2);
  EXPECT_EQ(m.vertex_count(), 8u * 6 * 4 * 3 + 8);
  EXPECT_EQ(m.edge_count(), 12u);  // 2 x 2 x 2 boxes: 4 lines per axis
}

TEST(Boxes, SphericalDomainOfFigure24) {
  // cos(2 |x|) on [-1, 1]^3, 41 samples per axis.
  const auto g = make_grid({41, 41, 41}, [](int i, int j, int k) {
    const double x = -1 + i / 20.0, y = -1 + j / 20.0, z = -1 + k / 20.0;
    return std::cos(2 * std::sqrt(x * x + y * y + z * z));
  }, {0.05, 0.05, 0.05}, {-1, -1, -1});
  BoxSettings s;
  s.gap = {2, 2, 2};
  s.face_cells = {4, 4};
  const double pi = std::acos(-1.0);
  const Mesh m = domain_boxes(*g.grid, g.domain, spherical_map(g.domain, {0, 0, 0}, {1, pi, 1.5 * pi}, {0, 0, 0}),
                              s, ColourSettings{});
  double largest = 0;
  for (size_t v = 0; v < m.vertex_count(); ++v) {
    const float* p = &m.points[3 * v];
    largest = std::max(largest, std::sqrt(double(p[0]) * p[0] + double(p[1]) * p[1] + double(p[2]) * p[2]));
  }
  // The outermost shell is u = 1: points on the unit sphere.
  EXPECT_NEAR(largest, 1.0, 1e-6);
  // The domain leaves the grid when the radius passes sqrt(3).
  EXPECT_THROW(domain_boxes(*g.grid, g.domain, spherical_map(g.domain, {0, 0, 0}, {2, pi, pi}, {0, 0, 0}), s,
                            ColourSettings{}),
               InvalidArgument);
}

TEST(Boxes, BadSettingsAreRefused) {
  const auto g = make_grid({5, 5, 5}, [](int, int, int) { return 1.0; });
  BoxSettings s;
  s.q = {5, 0, 5};
  try {
    domain_boxes(*g.grid, g.domain, box_map(g.domain), s, ColourSettings{});
    FAIL() << "q = 0 accepted";
  } catch (const InvalidArgument& e) {
    EXPECT_NE(std::string(e.what()).find("q = 0"), std::string::npos) << e.what();
  }
  s.q = {1, 1, 1};
  s.gap = {1, -1, 1};
  EXPECT_THROW(domain_boxes(*g.grid, g.domain, box_map(g.domain), s, ColourSettings{}), InvalidArgument);
  s.gap = {1, 1, 1};
  s.face_cells = {0, 1};
  EXPECT_THROW(domain_boxes(*g.grid, g.domain, box_map(g.domain), s, ColourSettings{}), InvalidArgument);
}

}  // namespace
}  // namespace isoform::visualize

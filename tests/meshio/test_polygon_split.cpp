// split_polygon: convex polygons keep the readers' fan exactly; concave ones
// become triangles that turn the polygon's way, cover its area and do not
// overlap; polygons without a plane or an ear fall back to the fan. Then the
// OBJ and PLY readers on a concave face.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "libcore/meshio/meshio.h"
#include "libcore/meshio/polygon_split.h"
#include "meshio_test_support.h"

namespace isoform::test {
namespace {

using meshio::split_polygon;
using Point2 = std::array<double, 2>;
using Point3 = std::array<double, 3>;

// Vertex numbers start here, so that a test sees corners mapped to vertices.
constexpr int32_t kFirstVertex = 7;

std::vector<int32_t> corner_vertices(size_t n) {
  std::vector<int32_t> corners;
  for (size_t i = 0; i < n; ++i) corners.push_back(kFirstVertex + int32_t(i));
  return corners;
}

std::vector<int32_t> split(const std::vector<Point3>& polygon) {
  std::vector<int32_t> out;
  split_polygon(corner_vertices(polygon.size()),
                [&](int32_t vertex) { return polygon.at(size_t(vertex - kFirstVertex)); }, out);
  return out;
}

std::vector<Point3> in_plane_z0(const std::vector<Point2>& polygon) {
  std::vector<Point3> points;
  for (const Point2& p : polygon) points.push_back({p[0], p[1], 0});
  return points;
}

std::vector<int32_t> fan(size_t n) {
  std::vector<int32_t> triangles;
  for (size_t k = 1; k + 1 < n; ++k) {
    triangles.insert(triangles.end(), {kFirstVertex, kFirstVertex + int32_t(k),
                                       kFirstVertex + int32_t(k + 1)});
  }
  return triangles;
}

double twice_area(const Point2& a, const Point2& b, const Point2& c) {
  return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
}

double twice_polygon_area(const std::vector<Point2>& polygon) {
  double twice = 0;
  for (size_t i = 0; i < polygon.size(); ++i) {
    const Point2& p = polygon[i];
    const Point2& q = polygon[(i + 1) % polygon.size()];
    twice += p[0] * q[1] - q[0] * p[1];
  }
  return twice;
}

using Triangle2 = std::array<Point2, 3>;

// Two counter-clockwise triangles have disjoint interiors exactly when the
// line of one of their six sides has the other triangle wholly on its outer
// side or on it.
bool side_separates(const Triangle2& t, const Triangle2& other) {
  for (int k = 0; k < 3; ++k) {
    bool all_outside = true;
    for (const Point2& p : other) {
      if (twice_area(t[size_t(k)], t[size_t((k + 1) % 3)], p) > 1e-12) all_outside = false;
    }
    if (all_outside) return true;
  }
  return false;
}

bool interiors_overlap(const Triangle2& a, const Triangle2& b) {
  return !side_separates(a, b) && !side_separates(b, a);
}

// The triangles of a split of polygon (vertex numbers from kFirstVertex), in
// the polygon's plane coordinates.
std::vector<Triangle2> triangles_of(const std::vector<int32_t>& out,
                                    const std::vector<Point2>& polygon) {
  std::vector<Triangle2> triangles;
  for (size_t t = 0; t + 2 < out.size(); t += 3) {
    Triangle2 triangle;
    for (size_t k = 0; k < 3; ++k) triangle[k] = polygon.at(size_t(out[t + k] - kFirstVertex));
    triangles.push_back(triangle);
  }
  return triangles;
}

// out splits polygon: n-2 triangles, each turning like the polygon, their
// areas adding up to the polygon's, no two interiors overlapping.
void expect_splits(const std::vector<int32_t>& out, const std::vector<Point2>& polygon) {
  ASSERT_EQ(out.size() % 3, 0u);
  ASSERT_EQ(out.size() / 3, polygon.size() - 2);
  double polygon_area = twice_polygon_area(polygon);
  double sign = polygon_area > 0 ? 1 : -1;
  std::vector<Triangle2> triangles = triangles_of(out, polygon);
  double sum = 0;
  for (size_t t = 0; t < triangles.size(); ++t) {
    const Triangle2& tri = triangles[t];
    double area = twice_area(tri[0], tri[1], tri[2]);
    EXPECT_GT(sign * area, 0) << "triangle " << t << " turns the other way or is flat";
    sum += area;
    // Made counter-clockwise for the overlap test.
    if (sign < 0) std::swap(triangles[t][1], triangles[t][2]);
  }
  EXPECT_NEAR(sum, polygon_area, 1e-9 * std::fabs(polygon_area));
  for (size_t a = 0; a < triangles.size(); ++a) {
    for (size_t b = a + 1; b < triangles.size(); ++b) {
      EXPECT_FALSE(interiors_overlap(triangles[a], triangles[b]))
          << "triangles " << a << " and " << b << " overlap";
    }
  }
}

// The concave pentagon of the OBJ face "f 2 3 4 5 1" over
// v 0 0 0 / v 2 0 0 / v 2 2 0 / v 1 0.5 0 / v 0 2 0.
std::vector<Point2> notched_square() { return {{2, 0}, {2, 2}, {1, 0.5}, {0, 2}, {0, 0}}; }

std::vector<Point2> l_shape() { return {{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}}; }

// A comb of teeth standing on a bar: teeth 1 wide, gaps 1 wide and 2 deep.
std::vector<Point2> comb(int teeth) {
  std::vector<Point2> polygon{{0, 0}, {2.0 * teeth - 1, 0}};
  for (int t = teeth - 1; t >= 0; --t) {
    polygon.push_back({2.0 * t + 1, 3});
    polygon.push_back({2.0 * t, 3});
    if (t > 0) {
      polygon.push_back({2.0 * t, 1});
      polygon.push_back({2.0 * t - 1, 1});
    }
  }
  return polygon;
}

// A five-pointed star, points of radius 2 and notches of radius 0.7,
// counter-clockwise, starting at a notch.
std::vector<Point2> star() {
  std::vector<Point2> polygon;
  const double pi = std::acos(-1.0);
  for (int k = 0; k < 10; ++k) {
    double radius = k % 2 == 0 ? 0.7 : 2.0;
    double angle = pi * k / 5;
    polygon.push_back({radius * std::cos(angle), radius * std::sin(angle)});
  }
  return polygon;
}

std::vector<Point2> reversed(std::vector<Point2> polygon) {
  std::reverse(polygon.begin(), polygon.end());
  return polygon;
}

// The plane point (x, y) at origin + x e1 + y e2, with e1, e2 orthonormal
// and e1 x e2 = normal.
std::vector<Point3> in_tilted_plane(const std::vector<Point2>& polygon, const Point3& origin,
                                    const Point3& e1, const Point3& e2) {
  std::vector<Point3> points;
  for (const Point2& p : polygon) {
    points.push_back({origin[0] + p[0] * e1[0] + p[1] * e2[0],
                      origin[1] + p[0] * e1[1] + p[1] * e2[1],
                      origin[2] + p[0] * e1[2] + p[1] * e2[2]});
  }
  return points;
}

Point3 normalized(const Point3& v) {
  double length = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  return {v[0] / length, v[1] / length, v[2] / length};
}

Point3 cross(const Point3& a, const Point3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

TEST(PolygonSplit, TrianglePassesThrough) {
  std::vector<int32_t> out{1, 2, 3};
  const double nan = std::numeric_limits<double>::quiet_NaN();
  split_polygon({9, 4, 6}, [&](int32_t) { return Point3{nan, nan, nan}; }, out);
  EXPECT_EQ(out, (std::vector<int32_t>{1, 2, 3, 9, 4, 6}));
}

TEST(PolygonSplit, FewerThanThreeCornersGiveNothing) {
  std::vector<int32_t> out;
  split_polygon({0, 1}, [](int32_t) { return Point3{0, 0, 0}; }, out);
  EXPECT_TRUE(out.empty());
}

TEST(PolygonSplit, ConvexPentagonIsTheFan) {
  std::vector<Point2> pentagon{{0, 0}, {2, 0}, {3, 1.5}, {1, 3}, {-1, 1.5}};
  EXPECT_EQ(split(in_plane_z0(pentagon)), fan(5));
  EXPECT_EQ(split(in_plane_z0(reversed(pentagon))), fan(5));
}

TEST(PolygonSplit, ConvexQuadInEveryAxisPlaneIsTheFan) {
  std::vector<Point3> xy{{0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  std::vector<Point3> yz{{4, 0, 0}, {4, 0, 1}, {4, 1, 1}, {4, 1, 0}};
  std::vector<Point3> zx{{0, -2, 0}, {0, -2, 1}, {1, -2, 1}, {1, -2, 0}};
  EXPECT_EQ(split(xy), fan(4));
  EXPECT_EQ(split(yz), fan(4));
  EXPECT_EQ(split(zx), fan(4));
}

TEST(PolygonSplit, ConcavePentagonIsCoveredWithoutOverlap) {
  std::vector<int32_t> out = split(in_plane_z0(notched_square()));
  EXPECT_EQ(out.size(), 9u);
  expect_splits(out, notched_square());
  EXPECT_DOUBLE_EQ(twice_polygon_area(notched_square()), 5.0);
  // The fan from corner 0 is exactly what must not come out.
  EXPECT_NE(out, fan(5));
}

TEST(PolygonSplit, LShapedHexagon) {
  expect_splits(split(in_plane_z0(l_shape())), l_shape());
  // Started at the reflex corner.
  std::vector<Point2> from_reflex{{1, 1}, {1, 2}, {0, 2}, {0, 0}, {2, 0}, {2, 1}};
  expect_splits(split(in_plane_z0(from_reflex)), from_reflex);
  // Started where the fan would leave the polygon.
  std::vector<Point2> from_outside_fan{{2, 1}, {1, 1}, {1, 2}, {0, 2}, {0, 0}, {2, 0}};
  std::vector<int32_t> out = split(in_plane_z0(from_outside_fan));
  expect_splits(out, from_outside_fan);
  EXPECT_NE(out, fan(6));
}

TEST(PolygonSplit, Comb) {
  std::vector<Point2> polygon = comb(4);
  ASSERT_EQ(polygon.size(), 16u);
  ASSERT_GT(twice_polygon_area(polygon), 0);
  expect_splits(split(in_plane_z0(polygon)), polygon);
}

TEST(PolygonSplit, Star) {
  expect_splits(split(in_plane_z0(star())), star());
}

TEST(PolygonSplit, ClockwisePolygonsStayClockwise) {
  for (const std::vector<Point2>& polygon :
       {reversed(notched_square()), reversed(l_shape()), reversed(comb(3)), reversed(star())}) {
    ASSERT_LT(twice_polygon_area(polygon), 0);
    expect_splits(split(in_plane_z0(polygon)), polygon);
  }
}

// The comb and the star in planes whose normals are largest in x, y and z,
// both ways, far from the origin.
TEST(PolygonSplit, TiltedPlanes) {
  const std::vector<Point3> normals{{3, 1, 2}, {-3, 1, 2}, {1, -3, 2}, {1, 3, -2}, {1, 2, -3}};
  for (const Point3& direction : normals) {
    Point3 normal = normalized(direction);
    Point3 e1 = normalized(cross(normal, Point3{0.3, 0.5, 0.7}));
    Point3 e2 = cross(normal, e1);
    for (const std::vector<Point2>& polygon : {comb(3), star(), reversed(l_shape())}) {
      std::vector<Point3> points = in_tilted_plane(polygon, {120, -45, 33}, e1, e2);
      std::vector<int32_t> out = split(points);
      SCOPED_TRACE(testing::Message() << "normal " << direction[0] << " " << direction[1] << " "
                                      << direction[2] << ", " << polygon.size() << " corners");
      expect_splits(out, polygon);
      // In space as well: every triangle faces the polygon's side.
      double sign = twice_polygon_area(polygon) > 0 ? 1 : -1;
      for (size_t t = 0; t < out.size(); t += 3) {
        const Point3& a = points[size_t(out[t] - kFirstVertex)];
        const Point3& b = points[size_t(out[t + 1] - kFirstVertex)];
        const Point3& c = points[size_t(out[t + 2] - kFirstVertex)];
        Point3 n = cross({b[0] - a[0], b[1] - a[1], b[2] - a[2]},
                         {c[0] - a[0], c[1] - a[1], c[2] - a[2]});
        EXPECT_GT(sign * (n[0] * normal[0] + n[1] * normal[1] + n[2] * normal[2]), 0);
      }
    }
  }
}

TEST(PolygonSplit, LongComb) {
  std::vector<Point2> polygon = comb(250);
  ASSERT_EQ(polygon.size(), 1000u);
  expect_splits(split(in_plane_z0(polygon)), polygon);
}

TEST(PolygonSplit, MoreCornersThanClippedAreTheFan) {
  std::vector<Point2> polygon = comb(int(meshio::kMostCornersToClip / 4) + 1);
  ASSERT_GT(polygon.size(), meshio::kMostCornersToClip);
  EXPECT_EQ(split(in_plane_z0(polygon)), fan(polygon.size()));
}

TEST(PolygonSplit, CollinearCornersAreTheFan) {
  std::vector<Point3> line{{0, 0, 0}, {1, 1, 1}, {3, 3, 3}, {2, 2, 2}, {-1, -1, -1}};
  EXPECT_EQ(split(line), fan(5));
}

TEST(PolygonSplit, RepeatedPointIsTheFan) {
  std::vector<Point3> same(6, Point3{1, 2, 3});
  EXPECT_EQ(split(same), fan(6));
}

TEST(PolygonSplit, NonFinitePointIsTheFan) {
  std::vector<Point3> points = in_plane_z0(notched_square());
  points[2][0] = std::numeric_limits<double>::infinity();
  EXPECT_EQ(split(points), fan(5));
  points[2][0] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(split(points), fan(5));
}

// A bow tie's two loops cancel: its Newell normal is zero.
TEST(PolygonSplit, BowTieIsTheFan) {
  std::vector<Point2> bow_tie{{0, 0}, {2, 2}, {2, 0}, {0, 2}};
  EXPECT_EQ(split(in_plane_z0(bow_tie)), fan(4));
}

// A flat corner on a side is not an ear, yet the polygon splits.
TEST(PolygonSplit, CornerOnASide) {
  std::vector<Point2> polygon{{0, 0}, {1, 0}, {2, 0}, {2, 2}, {1, 0.5}, {0, 2}};
  expect_splits(split(in_plane_z0(polygon)), polygon);
  // Convex but for the flat corner: not strictly convex, so clipped too.
  std::vector<Point2> square{{1, 0}, {2, 0}, {2, 2}, {0, 2}, {0, 0}};
  expect_splits(split(in_plane_z0(square)), square);
}

std::vector<Point2> plane_points(const Mesh& mesh) {
  std::vector<Point2> points;
  for (size_t v = 0; v < mesh.vertex_count(); ++v) {
    points.push_back({mesh.points[3 * v], mesh.points[3 * v + 1]});
  }
  return points;
}

// The mesh's triangles against its own points (numbered from kFirstVertex
// for expect_splits), as the polygon corners in the order given.
void expect_mesh_splits(const Mesh& mesh, const std::vector<int>& order) {
  std::vector<Point2> points = plane_points(mesh);
  std::vector<Point2> polygon;
  for (int v : order) polygon.push_back(points.at(size_t(v)));
  // Renumber the triangles' vertices to corner numbers.
  std::vector<int32_t> out;
  for (int32_t v : mesh.triangles) {
    auto at = std::find(order.begin(), order.end(), v);
    ASSERT_NE(at, order.end());
    out.push_back(kFirstVertex + int32_t(at - order.begin()));
  }
  expect_splits(out, polygon);
}

TEST(PolygonSplit, ObjConcaveFaceDoesNotOverlap) {
  TempDir dir;
  write_file(dir.file("notch.obj"),
             "v 0 0 0\nv 2 0 0\nv 2 2 0\nv 1 0.5 0\nv 0 2 0\nf 2 3 4 5 1\n");
  Mesh mesh = load_mesh(dir.file("notch.obj"));
  ASSERT_EQ(mesh.triangle_count(), 3u);
  expect_mesh_splits(mesh, {1, 2, 3, 4, 0});
}

TEST(PolygonSplit, PlyConcaveFaceDoesNotOverlapAndKeepsItsPart) {
  TempDir dir;
  write_file(dir.file("notch.ply"),
             "ply\nformat ascii 1.0\nelement vertex 5\nproperty float x\nproperty float y\n"
             "property float z\nelement face 2\nproperty list uchar int vertex_indices\n"
             "property uchar part\nend_header\n"
             "0 0 0\n2 0 0\n2 2 0\n1 0.5 0\n0 2 0\n5 1 2 3 4 0 2\n3 0 1 4 0\n");
  Mesh mesh = load_mesh(dir.file("notch.ply"));
  ASSERT_EQ(mesh.triangle_count(), 4u);
  EXPECT_EQ(mesh.parts, (std::vector<int32_t>{2, 2, 2, 0}));
  EXPECT_EQ(std::vector<int32_t>(mesh.triangles.end() - 3, mesh.triangles.end()),
            (std::vector<int32_t>{0, 1, 4}));
  mesh.triangles.resize(9);
  expect_mesh_splits(mesh, {1, 2, 3, 4, 0});
}

// With the faces before the vertices, no position is known while the faces
// are read: the fan from the first corner, as documented.
TEST(PolygonSplit, PlyFacesBeforeVerticesAreFanned) {
  TempDir dir;
  write_file(dir.file("faces_first.ply"),
             "ply\nformat ascii 1.0\nelement face 1\nproperty list uchar int vertex_indices\n"
             "element vertex 5\nproperty float x\nproperty float y\nproperty float z\n"
             "end_header\n5 1 2 3 4 0\n0 0 0\n2 0 0\n2 2 0\n1 0.5 0\n0 2 0\n");
  Mesh mesh = load_mesh(dir.file("faces_first.ply"));
  EXPECT_EQ(mesh.triangles, (std::vector<int32_t>{1, 2, 3, 1, 3, 4, 1, 4, 0}));
}

}  // namespace
}  // namespace isoform::test

// The proof that a graph-mode input's (x, y) projection is one-to-one
// (graph_embedding.h): proved on graphs over a square (the nine of Table
// 5.1 among them) and over a C-shaped
// strip; not proved for a strip that winds past a full turn (no overlap in
// space, but in the plane), one whose ends meet in the plane, or two
// patches. validate_graph names the first triangle that is not
// counterclockwise seen from +z. A graph-mode reduction of a mesh that the
// proof leaves undecided still meets the general check.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "libcore/errors.h"
#include "libcore/progress.h"
#include "libcore/reduce/graph_embedding.h"
#include "libcore/reduce/mesh_overlap.h"
#include "libcore/reduce/reduce.h"
#include "libcore/reduce/validate.h"
#include "libcore/vertex_stars.h"
#include "test_meshes.h"
#include "tests/curvature/truth.h"

namespace isoform::reduce {
namespace {

// The proof, after the checks it needs.
bool proved(const Mesh& m) {
  const VertexStars stars = vertex_stars(m);
  validate_manifold(m, stars, "test");
  validate_graph(m, "test");
  return projects_one_to_one(m, stars);
}

// validate_graph's message, or "" when it passes.
std::string graph_error(const Mesh& m) {
  try {
    validate_graph(m, "test");
  } catch (const InvalidArgument& e) {
    return e.what();
  }
  return "";
}

// plane_grid(n) with a bump for heights.
Mesh bumpy_grid(int n) {
  Mesh m = plane_grid(n);
  for (size_t v = 0; v < m.vertex_count(); ++v)
    m.points[3 * v + 2] = float(std::sin(0.7 * m.points[3 * v]) * std::cos(0.5 * m.points[3 * v + 1]));
  return m;
}

void turn_over(Mesh& m) {
  for (size_t t = 0; t < m.triangle_count(); ++t) std::swap(m.triangles[3 * t + 1], m.triangles[3 * t + 2]);
}

// A strip between radii 1 and 2 around the z axis, `turns` times around in
// n steps, rising by `rise` per radian, counter-clockwise seen from above.
Mesh strip(double turns, int n, double rise) {
  Mesh m;
  for (int i = 0; i <= n; ++i) {
    const double a = 2 * M_PI * turns * i / n;
    const auto exact = [](double c) { return std::fabs(c) < 1e-12 ? 0.0 : c; };  // at whole turns
    for (double r : {1.0, 2.0})
      m.points.insert(m.points.end(),
                      {float(r * exact(std::cos(a))), float(r * exact(std::sin(a))), float(rise * a)});
  }
  for (int32_t i = 0; i < n; ++i) {
    const int32_t in0 = 2 * i, out0 = 2 * i + 1, in1 = 2 * i + 2, out1 = 2 * i + 3;
    m.triangles.insert(m.triangles.end(), {in0, out0, out1, in0, out1, in1});
  }
  return m;
}

TEST(GraphEmbedding, AGridGraphIsProved) {
  EXPECT_TRUE(proved(bumpy_grid(30)));  // its boundary runs straight: collinear edges
  Mesh one;
  one.points = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  one.triangles = {0, 1, 2};
  EXPECT_TRUE(proved(one));
}

TEST(GraphEmbedding, AGraphTurnedOverIsRefusedByItsFirstTriangle) {
  Mesh m = bumpy_grid(5);
  turn_over(m);
  EXPECT_EQ(graph_error(m),
            "test: not a graph z = f(x, y): triangle 0 (vertices 0, 6, 1) does not turn counterclockwise seen "
            "from +z (graph mode needs every triangle so, the normals up)");
}

TEST(GraphEmbedding, TheTable51GraphsAreProved) {
  for (const truth::Graph& g : truth::table41_graphs()) EXPECT_TRUE(proved(truth::graph_mesh(g, 51))) << g.name;
}

TEST(GraphEmbedding, ACShapedStripIsProved) {
  EXPECT_TRUE(proved(strip(0.9, 60, 0.3)));
  EXPECT_TRUE(proved(strip(0.9, 60, 0.0)));
}

TEST(GraphEmbedding, AStripPastAFullTurnIsNotProved) {
  // 1.25 turns rising: apart in space, over itself in the plane.
  const Mesh m = strip(1.25, 80, 0.3);
  EXPECT_TRUE(find_overlaps(m).empty());
  EXPECT_FALSE(proved(m));
}

TEST(GraphEmbedding, AStripWhoseEndsMeetInThePlaneIsNotProved) {
  // Exactly one turn: the last cross edge lies on the first in (x, y),
  // 0.3 * 2 pi above it.
  const Mesh m = strip(1.0, 64, 0.3);
  EXPECT_TRUE(find_overlaps(m).empty());
  EXPECT_FALSE(proved(m));
}

TEST(GraphEmbedding, AFoldedOrVerticalTriangleIsRefused) {
  // Vertex 65 at (5, 5) pushed to (6.5, 5), past its neighbour 66 at (6, 5):
  // triangles 99 (53, 66, 65) and 120 (65, 66, 78) turn clockwise.
  Mesh m = bumpy_grid(12);
  const size_t v = 5 * 12 + 5;
  m.points[3 * v] = 6.5f;
  const std::string named = "test: not a graph z = f(x, y): triangle 99 (vertices 53, 66, 65) ";
  EXPECT_EQ(graph_error(m).rfind(named, 0), 0u) << graph_error(m);
  // At (5.5, 4.5), on the line through 53 (5, 4) and 66 (6, 5): triangle 99
  // alone is vertical.
  m.points[3 * v] = 5.5f;
  m.points[3 * v + 1] = 4.5f;
  EXPECT_EQ(graph_error(m).rfind(named, 0), 0u) << graph_error(m);
  m.points[3 * v] = 5.4f;
  EXPECT_EQ(graph_error(m), "");
}

TEST(GraphEmbedding, ThePreciseCoordinatesAreTheOnesJudged) {
  // Float points of a C-shaped strip, precise points of one that overlaps
  // itself in the plane: both checks read the precise ones.
  Mesh m = strip(0.9, 60, 0.0);
  const Mesh over = strip(1.25, 60, 0.0);
  m.precise_points.assign(over.points.begin(), over.points.end());
  EXPECT_FALSE(proved(m));
  EXPECT_FALSE(find_overlaps(m).empty());
  m.precise_points.clear();
  EXPECT_TRUE(proved(m));
}

TEST(GraphEmbedding, AFoldBelowRoundingIsProvedThoughTheGeneralCheckRefusesIt) {
  // Two near-vertical slivers on the edge (0, 0, 0)-(0, 1, 0), their tips
  // 2e-15 apart in x: both certainly counterclockwise seen from +z, one
  // simple boundary loop, so no overlap, exactly. The general check calls
  // triangles sharing an edge coplanar within a rounding tolerance and then
  // sees a fold: it is stricter here (docs/reduce.md, "Graph inputs").
  Mesh m;
  m.precise_points = {0, 0, 0, 0, 1, 0, -1e-15, 0.5, 1, 1e-15, 0.5, 1};
  m.points.assign(m.precise_points.begin(), m.precise_points.end());
  m.triangles = {0, 1, 2, 1, 0, 3};
  EXPECT_TRUE(proved(m));
  EXPECT_FALSE(find_overlaps(m).empty());
}

TEST(GraphEmbedding, EdgesBeyondTheDecidableScaleAreRefused) {
  Mesh m = plane_grid(4);
  for (double scale : {1e-100, 1e-160}) {
    m.precise_points.assign(m.points.begin(), m.points.end());
    for (double& c : m.precise_points) c *= scale;
    EXPECT_EQ(graph_error(m).empty(), scale > 1e-150) << scale << ": " << graph_error(m);
  }
}

TEST(GraphEmbedding, TwoPatchesOrAClosedSurfaceAreNotProved) {
  Mesh two = plane_grid(6);
  const Mesh other = plane_grid(6);
  const int32_t base = int32_t(two.vertex_count());
  for (size_t v = 0; v < other.vertex_count(); ++v)
    two.points.insert(two.points.end(), {other.points[3 * v] + 10, other.points[3 * v + 1], 0.0f});
  for (int32_t i : other.triangles) two.triangles.push_back(base + i);
  EXPECT_FALSE(proved(two));  // two boundary loops: not decided, left to the general check
  Mesh torus;
  add_torus(torus, 12, 16, 3, 1, {0, 0, 0});
  EXPECT_NE(graph_error(torus), "");  // half of it turns clockwise
}

// reduce_mesh's message for m in graph mode, or "" when it reduces.
std::string graph_reduce_error(Mesh m) {
  ReduceOptions o;
  o.graph = true;
  o.keep_fraction = 0.5;
  try {
    reduce_mesh(m, o, Progress(nullptr));
  } catch (const InvalidArgument& e) {
    return e.what();
  }
  return "";
}

TEST(GraphEmbedding, AGraphModeReductionRefusesWhatIsNoGraphOrOverlaps) {
  Mesh turned = bumpy_grid(5);
  turn_over(turned);
  EXPECT_EQ(graph_reduce_error(turned).rfind("reduce: not a graph z = f(x, y): triangle 0 ", 0), 0u)
      << graph_reduce_error(turned);
  // Flat, 1.25 turns: counterclockwise everywhere, but its end lies on its
  // start. The proof fails, the general check runs and names the overlap.
  const Mesh flat = strip(1.25, 80, 0.0);
  ASSERT_FALSE(find_overlaps(flat).empty());
  EXPECT_EQ(graph_reduce_error(flat).rfind("reduce: the mesh overlaps itself: triangles ", 0), 0u)
      << graph_reduce_error(flat);
  // Rising, it does not overlap, and reduces.
  EXPECT_EQ(graph_reduce_error(strip(1.25, 80, 0.3)), "");
  EXPECT_EQ(graph_reduce_error(bumpy_grid(12)), "");
}

}  // namespace
}  // namespace isoform::reduce

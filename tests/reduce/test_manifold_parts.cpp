// The reduction's option manifold_parts_only: parts that fail an entry check
// (a fin, a bowtie vertex, an overlap, a NaN) are copied unchanged with the
// first offender of each named, the others are reduced with keep_fraction of
// their own triangles.
#include <gtest/gtest.h>

#include <limits>
#include <map>
#include <utility>

#include "libcore/errors.h"
#include "libcore/reduce/reduce.h"
#include "test_meshes.h"

namespace isoform {
namespace {

using reduce::add_torus;

void add(Mesh& m, std::initializer_list<float> points, std::initializer_list<int32_t> triangles, float dx) {
  const int32_t base = int32_t(m.vertex_count());
  size_t k = 0;
  for (float p : points) m.points.push_back(k++ % 3 == 0 ? p + dx : p);
  for (int32_t v : triangles) m.triangles.push_back(base + v);
}

// A 768-triangle torus (vertices 0-383), a fin of three triangles on the edge
// (384, 385) (triangles 768-770), and a bowtie of two triangles meeting at
// vertex 389 (triangles 771 and 772).
Mesh torus_fin_bowtie() {
  Mesh m;
  add_torus(m, 24, 16, 2, 0.7, {0, 0, 0});
  add(m, {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 1}, {0, 1, 2, 1, 0, 3, 0, 1, 4}, 10);
  add(m, {0, 0, 0, 1, 0, 0, 1, 1, 0, -1, 0, 0, -1, -1, 0}, {0, 1, 2, 0, 3, 4}, 20);
  return m;
}

std::array<float, 9> corners(const Mesh& m, size_t t) {
  std::array<float, 9> c{};
  for (size_t k = 0; k < 3; ++k)
    for (size_t i = 0; i < 3; ++i) c[3 * k + i] = m.points[3 * size_t(m.triangles[3 * t + k]) + i];
  return c;
}

// Closed surface: every edge in exactly two of the triangles [0, count).
void expect_closed(const Mesh& m, size_t count, long long euler) {
  std::map<std::pair<int32_t, int32_t>, int> edges;
  std::map<int32_t, int> vertices;
  for (size_t t = 0; t < count; ++t)
    for (size_t k = 0; k < 3; ++k) {
      const int32_t a = m.triangles[3 * t + k], b = m.triangles[3 * t + (k + 1) % 3];
      ++edges[{std::min(a, b), std::max(a, b)}];
      ++vertices[a];
    }
  for (const auto& [e, n] : edges) EXPECT_EQ(n, 2) << e.first << ", " << e.second;
  EXPECT_EQ((long long)vertices.size() - (long long)edges.size() + (long long)count, euler);
}

ReduceStats reduce_parts(Mesh& m, double keep) {
  ReduceOptions o;
  o.keep_fraction = keep;
  o.manifold_parts_only = true;
  return reduce_mesh(m, o, Progress(nullptr));
}

TEST(ManifoldParts, BadPartsAreCopiedAndNamedTheRestIsReduced) {
  Mesh m = torus_fin_bowtie();
  const Mesh input = m;
  ReduceOptions plain;
  plain.keep_fraction = 0.5;
  try {
    reduce_mesh(m, plain, Progress(nullptr));
    ADD_FAILURE() << "a fin accepted without the option";
  } catch (const InvalidArgument& e) {
    EXPECT_NE(std::string(e.what()).find("edge (384, 385) is shared by 3 triangles"), std::string::npos) << e.what();
  }
  const ReduceStats s = reduce_parts(m, 0.5);
  EXPECT_EQ(s.parts_left_alone, 3);  // the fin, and each wing of the bowtie (parts by edges)
  EXPECT_EQ(s.triangles_left_alone, 5);
  ASSERT_EQ(s.left_alone.size(), 3u);
  EXPECT_EQ(s.left_alone[0],
            "part of 3 triangles from triangle 768: the mesh is not manifold: edge (384, 385) is shared by 3 triangles");
  EXPECT_EQ(s.left_alone[1],
            "part of 1 triangle from triangle 771: the mesh is not manifold at vertex 389: its triangles form more "
            "than one fan");
  EXPECT_EQ(s.left_alone[2],
            "part of 1 triangle from triangle 772: the mesh is not manifold at vertex 389: its triangles form more "
            "than one fan");
  EXPECT_EQ(s.triangles_before, 773);
  EXPECT_EQ(s.vertices_before, 394);
  EXPECT_EQ(s.triangles_after, (long long)m.triangle_count());
  // keep_fraction counts the torus's 768 triangles: 384, reached to within one removal (4 triangles).
  const size_t reduced = m.triangle_count() - 5;
  EXPECT_LE(reduced, 384u);
  EXPECT_GT(reduced, 380u);
  EXPECT_GT(s.removals, 0);
  expect_closed(m, reduced, 0);  // still a torus
  // The parts left alone follow, as they were.
  for (size_t t = 0; t < 5; ++t) EXPECT_EQ(corners(m, reduced + t), corners(input, 768 + t)) << t;
  EXPECT_EQ(m.vertex_count(), reduced / 2 + 10);  // torus: V = F / 2; then the 10 vertices left alone
  EXPECT_EQ(m.curvature.k1.size(), m.vertex_count());
  EXPECT_EQ(m.normals.size(), m.points.size());
}

TEST(ManifoldParts, BothPartsOfAnOverlapAreLeftAlone) {
  Mesh m;
  add_torus(m, 16, 12, 2, 0.5, {0, 0, 0});      // triangles 0-383
  add_torus(m, 16, 12, 2, 0.5, {1.5, 0.3, 0.2});  // 384-767, through the first
  add_torus(m, 24, 16, 2, 0.7, {10, 0, 0});      // 768-1535, apart
  const ReduceStats s = reduce_parts(m, 0.25);
  ASSERT_EQ(s.parts_left_alone, 2);
  EXPECT_EQ(s.triangles_left_alone, 768);
  EXPECT_EQ(s.left_alone[0].rfind("part of 384 triangles from triangle 0: the mesh overlaps itself: triangles ", 0), 0u)
      << s.left_alone[0];
  EXPECT_EQ(s.left_alone[1].rfind("part of 384 triangles from triangle 384: the mesh overlaps itself: triangles ", 0),
            0u)
      << s.left_alone[1];
  EXPECT_LE(m.triangle_count() - 768, 192u);
  EXPECT_GT(m.triangle_count() - 768, 188u);
}

TEST(ManifoldParts, ANonFiniteVertexLeavesItsPartAlone) {
  Mesh m;
  add_torus(m, 24, 16, 2, 0.7, {0, 0, 0});
  add(m, {0, 0, 0, 1, 0, 0, 0, 1, 0}, {0, 1, 2}, 10);
  m.points[3 * 385 + 1] = std::numeric_limits<float>::quiet_NaN();
  const ReduceStats s = reduce_parts(m, 0.5);
  ASSERT_EQ(s.left_alone.size(), 1u);
  EXPECT_EQ(s.left_alone[0],
            "part of 1 triangle from triangle 768: vertex 385 has a coordinate that is not finite (NaN or infinity)");
  EXPECT_LE(m.triangle_count(), 385u);
}

TEST(ManifoldParts, KeepAllOrNothingReducibleLeavesTheMeshAsItIs) {
  Mesh m = torus_fin_bowtie();
  const Mesh input = m;
  const ReduceStats s = reduce_parts(m, 1.0);
  EXPECT_EQ(m.points, input.points);
  EXPECT_EQ(m.triangles, input.triangles);
  EXPECT_EQ(s.parts_left_alone, 3);
  EXPECT_EQ(s.triangles_after, 773);
  Mesh fin;
  add(fin, {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 1}, {0, 1, 2, 1, 0, 3, 0, 1, 4}, 0);
  const Mesh fin_input = fin;
  const ReduceStats f = reduce_parts(fin, 0.1);
  EXPECT_EQ(fin.triangles, fin_input.triangles);
  EXPECT_EQ(f.parts_left_alone, 1);
  EXPECT_EQ(f.removals, 0);
}

TEST(ManifoldParts, AGoodMeshIsThePlainReduction) {
  Mesh a, b;
  add_torus(a, 24, 16, 2, 0.7, {0, 0, 0});
  b = a;
  const ReduceStats s = reduce_parts(a, 0.3);
  ReduceOptions plain;
  plain.keep_fraction = 0.3;
  reduce_mesh(b, plain, Progress(nullptr));
  EXPECT_EQ(s.parts_left_alone, 0);
  EXPECT_TRUE(s.left_alone.empty());
  EXPECT_EQ(a.triangles, b.triangles);
  EXPECT_EQ(a.points, b.points);
}

}  // namespace
}  // namespace isoform

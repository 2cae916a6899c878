// The star table (vertex_stars.h) on a hand-checkable mesh and on one large
// enough for its stretches side by side, and the manifold checks that read
// it against a plain reference on meshes with random defects.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <functional>
#include <map>
#include <random>

#include "libcore/errors.h"
#include "libcore/reduce/validate.h"
#include "libcore/vertex_stars.h"
#include "test_meshes.h"

namespace isoform::reduce {
namespace {

std::vector<int32_t> star(const VertexStars& s, size_t v) { return {s.begin(v), s.end(v)}; }

TEST(VertexStars, EachVertexListsItsTrianglesAscending) {
  Mesh square;  // two triangles over the unit square
  square.points = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
  square.triangles = {0, 1, 2, 0, 2, 3};
  const VertexStars s = vertex_stars(square);
  ASSERT_EQ(s.vertex_count(), 4u);
  EXPECT_EQ(star(s, 0), (std::vector<int32_t>{0, 1}));
  EXPECT_EQ(star(s, 1), (std::vector<int32_t>{0}));
  EXPECT_EQ(star(s, 2), (std::vector<int32_t>{0, 1}));
  EXPECT_EQ(star(s, 3), (std::vector<int32_t>{1}));
}

TEST(VertexStars, LargeMeshesGiveWhatOneScanGives) {
  Mesh torus;  // 2 x 200 x 200 triangles: the table is built in stretches
  add_torus(torus, 200, 200, 2, 0.7, {0, 0, 0});
  const VertexStars s = vertex_stars(torus);
  std::vector<std::vector<int32_t>> scan(torus.vertex_count());
  for (size_t t = 0; t < torus.triangle_count(); ++t)
    for (int k = 0; k < 3; ++k) scan[size_t(torus.triangles[3 * t + size_t(k)])].push_back(int32_t(t));
  ASSERT_EQ(s.vertex_count(), scan.size());
  for (size_t v = 0; v < scan.size(); ++v) ASSERT_EQ(star(s, v), scan[v]) << "vertex " << v;
  EXPECT_EQ(s.faces.size(), 3 * torus.triangle_count());
}

// The reference: no triangle uses a vertex twice, every undirected edge is
// in at most two triangles and then in opposite directions, and around
// every vertex the edges opposite it are connected (one fan).
bool manifold_by_reference(const Mesh& m) {
  std::map<std::pair<int32_t, int32_t>, int> directed;
  for (size_t t = 0; t < m.triangle_count(); ++t) {
    const int32_t* v = &m.triangles[3 * t];
    if (v[0] == v[1] || v[1] == v[2] || v[2] == v[0]) return false;
    for (int k = 0; k < 3; ++k) ++directed[{v[k], v[(k + 1) % 3]}];
  }
  // At most once each way: at most two triangles, in opposite directions.
  for (const auto& [edge, uses] : directed)
    if (uses > 1) return false;
  std::vector<std::vector<std::array<int32_t, 2>>> link(m.vertex_count());
  for (size_t t = 0; t < m.triangle_count(); ++t)
    for (int k = 0; k < 3; ++k)
      link[size_t(m.triangles[3 * t + size_t(k)])].push_back(
          {m.triangles[3 * t + size_t((k + 1) % 3)], m.triangles[3 * t + size_t((k + 2) % 3)]});
  for (const auto& edges : link) {  // connected: a union of the link's vertices
    std::map<int32_t, int32_t> parent;
    std::function<int32_t(int32_t)> root = [&](int32_t x) { return parent[x] == x ? x : parent[x] = root(parent[x]); };
    for (const auto& e : edges)
      for (int32_t x : e)
        if (!parent.count(x)) parent[x] = x;
    for (const auto& e : edges) parent[root(e[0])] = root(e[1]);
    int roots = 0;
    for (const auto& [x, p] : parent) roots += int(root(x) == x);
    if (roots > 1) return false;
  }
  return true;
}

bool manifold_by_check(const Mesh& m) {
  try {
    validate_indices(m, "test");
    validate_manifold(m, vertex_stars(m), "test");
    return true;
  } catch (const InvalidArgument&) {
    return false;
  }
}

TEST(VertexStars, TheManifoldChecksAgreeWithAPlainReference) {
  // A torus with one defect at random: a corner moved to another vertex (a
  // vertex used twice, a fin, two fans), a triangle turned over, a copy of
  // a triangle either way round, a triangle taken out (a boundary: fine),
  // or two far apart triangles taken out and a third rewired.
  std::mt19937 rng(27);
  int refused = 0, accepted = 0;
  for (int trial = 0; trial < 600; ++trial) {
    Mesh m;
    add_torus(m, 10, 8, 2, 0.7, {0, 0, 0});
    std::uniform_int_distribution<size_t> tri(0, m.triangle_count() - 1);
    std::uniform_int_distribution<int32_t> vert(0, int32_t(m.vertex_count()) - 1);
    const size_t t = tri(rng);
    switch (trial % 5) {
      case 0: m.triangles[3 * t + size_t(trial / 5 % 3)] = vert(rng); break;
      case 1: std::swap(m.triangles[3 * t], m.triangles[3 * t + 1]); break;
      case 2: {
        std::vector<int32_t> copy(m.triangles.begin() + std::ptrdiff_t(3 * t), m.triangles.begin() + std::ptrdiff_t(3 * t + 3));
        if (trial % 2) std::swap(copy[0], copy[1]);
        m.triangles.insert(m.triangles.end(), copy.begin(), copy.end());
        break;
      }
      case 3: m.triangles.erase(m.triangles.begin() + std::ptrdiff_t(3 * t), m.triangles.begin() + std::ptrdiff_t(3 * t + 3)); break;
      case 4: {
        const size_t u = tri(rng);
        m.triangles[3 * u + 2] = m.triangles[3 * t];
        break;
      }
    }
    const bool reference = manifold_by_reference(m);
    EXPECT_EQ(manifold_by_check(m), reference) << "trial " << trial;
    (reference ? accepted : refused) += 1;
  }
  EXPECT_GT(refused, 200);  // the sample has defects to find
  EXPECT_GT(accepted, 100);  // and meshes that pass
}

// A vertex is on the boundary when one of its edges lies in one triangle:
// counted over an edge table, as a reference for the flags the manifold
// check gives (the working mesh takes them instead of finding them again).
std::vector<uint8_t> boundary_by_edges(const Mesh& m) {
  std::map<std::pair<int32_t, int32_t>, int> uses;
  for (size_t t = 0; t < m.triangle_count(); ++t)
    for (int k = 0; k < 3; ++k) {
      const int32_t a = m.triangles[3 * t + size_t(k)], b = m.triangles[3 * t + size_t((k + 1) % 3)];
      ++uses[{std::min(a, b), std::max(a, b)}];
    }
  std::vector<uint8_t> on(m.vertex_count(), 0);
  for (const auto& [edge, count] : uses)
    if (count == 1) on[size_t(edge.first)] = on[size_t(edge.second)] = 1;
  return on;
}

TEST(VertexStars, TheManifoldCheckTellsTheBoundaryVertices) {
  std::vector<Mesh> meshes;
  meshes.push_back(plane_grid(9));  // the border's 32 vertices
  Mesh torus;
  add_torus(torus, 10, 8, 2, 0.7, {0, 0, 0});
  meshes.push_back(torus);  // none
  Mesh holes = torus;  // two triangles out: their six vertices
  holes.triangles.erase(holes.triangles.begin() + 30, holes.triangles.begin() + 33);
  holes.triangles.erase(holes.triangles.begin() + 90, holes.triangles.begin() + 93);
  meshes.push_back(holes);
  Mesh single;  // one triangle, and a vertex in none
  single.points = {0, 0, 0, 1, 0, 0, 0, 1, 0, 5, 5, 5};
  single.triangles = {0, 1, 2};
  meshes.push_back(single);
  const size_t expected[] = {32, 0, 6, 3};
  for (size_t i = 0; i < meshes.size(); ++i) {
    std::vector<uint8_t> flags;
    validate_manifold(meshes[i], vertex_stars(meshes[i]), "test", &flags);
    EXPECT_EQ(flags, boundary_by_edges(meshes[i])) << "mesh " << i;
    EXPECT_EQ(size_t(std::count(flags.begin(), flags.end(), uint8_t(1))), expected[i]) << "mesh " << i;
  }
  // The random defects' tori that pass (a triangle or two taken out, so
  // boundaries of every shape the sample makes).
  std::mt19937 rng(5);
  int open = 0;
  for (int trial = 0; trial < 200; ++trial) {
    Mesh m = torus;
    std::uniform_int_distribution<size_t> tri(0, m.triangle_count() - 1);
    for (int k = 0; k <= trial % 3; ++k) {
      const size_t t = tri(rng) % m.triangle_count();
      m.triangles.erase(m.triangles.begin() + std::ptrdiff_t(3 * t), m.triangles.begin() + std::ptrdiff_t(3 * t + 3));
    }
    std::vector<uint8_t> flags;
    try {
      validate_manifold(m, vertex_stars(m), "test", &flags);
    } catch (const InvalidArgument&) {
      continue;  // (two holes meeting at a vertex: two fans)
    }
    EXPECT_EQ(flags, boundary_by_edges(m)) << "trial " << trial;
    open += int(std::count(flags.begin(), flags.end(), uint8_t(1)) > 0);
  }
  EXPECT_GT(open, 150);
}

}  // namespace
}  // namespace isoform::reduce

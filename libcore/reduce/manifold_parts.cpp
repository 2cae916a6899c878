// Reducing only the parts that pass the entry checks (see manifold_parts.h).
#include "manifold_parts.h"

#include <algorithm>
#include <array>
#include <numeric>
#include <string>

#include "../mesh_normals.h"
#include "../topology.h"
#include "validate.h"

namespace isoform::reduce {
namespace {

int32_t find(std::vector<int32_t>& parent, int32_t i) {
  while (parent[size_t(i)] != i) i = parent[size_t(i)] = parent[size_t(parent[size_t(i)])];
  return i;
}

// Part of each triangle over shared edges, numbered in the order of their
// first triangle.
std::vector<int32_t> edge_parts(const Mesh& mesh, int32_t* count) {
  const size_t nt = mesh.triangle_count();
  std::vector<std::array<int32_t, 3>> edges;  // lo, hi, triangle
  edges.reserve(3 * nt);
  for (size_t t = 0; t < nt; ++t)
    for (int k = 0; k < 3; ++k) {
      const int32_t a = mesh.triangles[3 * t + size_t(k)], b = mesh.triangles[3 * t + size_t(k + 1) % 3];
      if (a != b) edges.push_back({std::min(a, b), std::max(a, b), int32_t(t)});
    }
  std::sort(edges.begin(), edges.end());
  std::vector<int32_t> parent(nt);
  std::iota(parent.begin(), parent.end(), 0);
  for (size_t i = 1; i < edges.size(); ++i)
    if (edges[i][0] == edges[i - 1][0] && edges[i][1] == edges[i - 1][1])
      parent[size_t(find(parent, edges[i][2]))] = find(parent, edges[i - 1][2]);
  std::vector<int32_t> number(nt, -1), part(nt);
  *count = 0;
  for (size_t t = 0; t < nt; ++t) {
    int32_t& n = number[size_t(find(parent, int32_t(t)))];
    if (n < 0) n = (*count)++;
    part[t] = n;
  }
  return part;
}

struct Classified {
  std::vector<int32_t> part;      // per triangle
  std::vector<std::string> why;   // per part: the first violation, "" when it passes
  std::vector<long long> size;    // per part: triangles
  std::vector<int32_t> first;     // per part: its smallest triangle
};

Classified classify(const Mesh& mesh) {
  Classified c;
  int32_t parts = 0;
  c.part = edge_parts(mesh, &parts);
  c.why.resize(size_t(parts));
  c.size.assign(size_t(parts), 0);
  c.first.assign(size_t(parts), -1);
  for (size_t t = 0; t < c.part.size(); ++t) {
    const size_t p = size_t(c.part[t]);
    ++c.size[p];
    if (c.first[p] < 0) c.first[p] = int32_t(t);
  }
  // The triangles of each vertex, for violations at a vertex.
  const size_t nv = mesh.vertex_count();
  std::vector<int32_t> start(nv + 1, 0), around(mesh.triangles.size());
  for (int32_t v : mesh.triangles) ++start[size_t(v) + 1];
  for (size_t v = 0; v < nv; ++v) start[v + 1] += start[v];
  std::vector<int32_t> fill(start.begin(), start.end() - 1);
  for (size_t i = 0; i < mesh.triangles.size(); ++i) around[size_t(fill[size_t(mesh.triangles[i])]++)] = int32_t(i / 3);
  auto mark = [&](int32_t t, const std::string& problem) {
    std::string& why = c.why[size_t(c.part[size_t(t)])];
    if (why.empty()) why = problem;
  };
  find_offences(mesh, "reduce", [&](const Offence& o) {
    if (o.triangle >= 0) mark(o.triangle, o.problem);
    if (o.other >= 0) mark(o.other, o.problem);
    if (o.vertex >= 0)
      for (int32_t i = start[size_t(o.vertex)]; i < start[size_t(o.vertex) + 1]; ++i) mark(around[size_t(i)], o.problem);
    return true;
  });
  return c;
}

// The triangles with take[t] and the vertices they use, renumbered in order.
Mesh sub_mesh(const Mesh& m, const std::vector<char>& take) {
  const size_t nv = m.vertex_count();
  std::vector<int32_t> map(nv, -1);
  Mesh out;
  const bool precise = m.precise_points.size() == 3 * nv, normals = m.normals.size() == 3 * nv;
  const VertexCurvature& c = m.curvature;
  const bool curved = c.k1.size() == nv;
  VertexCurvature& d = out.curvature;
  auto add_vertex = [&](size_t v) {
    for (size_t k = 0; k < 3; ++k) {
      out.points.push_back(m.points[3 * v + k]);
      if (precise) out.precise_points.push_back(m.precise_points[3 * v + k]);
      if (normals) out.normals.push_back(m.normals[3 * v + k]);
      if (curved) {
        d.d1.push_back(c.d1[3 * v + k]);
        d.d2.push_back(c.d2[3 * v + k]);
      }
    }
    if (curved) {
      d.k1.push_back(c.k1[v]);
      d.k2.push_back(c.k2[v]);
      d.mean.push_back(c.mean[v]);
      d.gauss.push_back(c.gauss[v]);
      d.absolute.push_back(c.absolute[v]);
      d.flags.push_back(c.flags[v]);
    }
  };
  for (size_t t = 0; t < m.triangle_count(); ++t) {
    if (!take[t]) continue;
    for (size_t k = 0; k < 3; ++k) {
      const size_t v = size_t(m.triangles[3 * t + k]);
      if (map[v] < 0) {
        map[v] = int32_t(out.vertex_count());
        add_vertex(v);
      }
      out.triangles.push_back(map[v]);
    }
  }
  if (curved) d.stats = c.stats;
  out.contour = m.contour;
  return out;
}

// The reduced parts, then the parts left alone (which get curvature 0,
// flagged failed, when they have none).
Mesh joined(Mesh reduced, const Mesh& rest) {
  const size_t base = reduced.vertex_count(), nv = rest.vertex_count();
  Mesh out = std::move(reduced);
  out.points.insert(out.points.end(), rest.points.begin(), rest.points.end());
  if (!out.precise_points.empty())
    out.precise_points.insert(out.precise_points.end(), rest.precise_points.begin(), rest.precise_points.end());
  Mesh normals_of_rest;
  const std::vector<float>* rest_normals = &rest.normals;
  if (rest.normals.size() != rest.points.size()) {
    normals_of_rest.points = rest.points;
    normals_of_rest.triangles = rest.triangles;
    estimate_normals(normals_of_rest);
    rest_normals = &normals_of_rest.normals;
  }
  out.normals.insert(out.normals.end(), rest_normals->begin(), rest_normals->end());
  VertexCurvature& c = out.curvature;
  const VertexCurvature& r = rest.curvature;
  const bool has = r.k1.size() == nv;
  auto append = [&](std::vector<float>& to, const std::vector<float>& from, size_t per) {
    if (has) to.insert(to.end(), from.begin(), from.end());
    else to.resize(to.size() + per * nv, 0.0f);
  };
  for (auto [to, from] : {std::pair{&c.k1, &r.k1}, {&c.k2, &r.k2}, {&c.mean, &r.mean}, {&c.gauss, &r.gauss},
                          {&c.absolute, &r.absolute}})
    append(*to, *from, 1);
  append(c.d1, r.d1, 3);
  append(c.d2, r.d2, 3);
  if (has) c.flags.insert(c.flags.end(), r.flags.begin(), r.flags.end());
  else c.flags.resize(c.flags.size() + nv, kCurvatureFailed);
  c.stats.vertices = (long long)out.vertex_count();
  for (int32_t v : rest.triangles) out.triangles.push_back(v + int32_t(base));
  out.colors.clear();
  out.edges.clear();
  compute_topology(out);
  return out;
}

}  // namespace

ReduceStats reduce_manifold_parts(Mesh& mesh, const ReduceOptions& options, const Progress& progress) {
  ReduceOptions plain = options;
  plain.manifold_parts_only = false;
  const long long triangles_in = (long long)mesh.triangle_count(), vertices_in = (long long)mesh.vertex_count();
  const Classified c = classify(mesh);
  std::vector<char> good(mesh.triangle_count());
  for (size_t t = 0; t < good.size(); ++t) good[t] = c.why[size_t(c.part[t])].empty();
  ReduceStats alone;
  for (size_t p = 0; p < c.why.size(); ++p) {
    if (c.why[p].empty()) continue;
    ++alone.parts_left_alone;
    alone.triangles_left_alone += c.size[p];
    alone.left_alone.push_back("part of " + std::to_string(c.size[p]) + " triangle" + (c.size[p] == 1 ? "" : "s") +
                               " from triangle " + std::to_string(c.first[p]) + ": " + c.why[p]);
  }
  if (alone.parts_left_alone == 0) return reduce_mesh(mesh, plain, progress);
  const long long reducible = (long long)mesh.triangle_count() - alone.triangles_left_alone;
  ReduceStats s;
  if (options.keep_fraction < 1.0 && reducible > 0) {
    Mesh part = sub_mesh(mesh, good);
    s = reduce_mesh(part, plain, progress);
    for (char& g : good) g = !g;
    Mesh out = joined(std::move(part), sub_mesh(mesh, good));
    mesh = std::move(out);
  }
  s.triangles_before = triangles_in;
  s.vertices_before = vertices_in;
  s.triangles_after = (long long)mesh.triangle_count();
  s.vertices_after = (long long)mesh.vertex_count();
  s.parts_left_alone = alone.parts_left_alone;
  s.triangles_left_alone = alone.triangles_left_alone;
  s.left_alone = std::move(alone.left_alone);
  return s;
}

}  // namespace isoform::reduce

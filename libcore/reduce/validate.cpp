// Entry checks of the reduction (see validate.h).
#include "validate.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

#include "../errors.h"
#include "mesh_overlap.h"

namespace isoform::reduce {
namespace {

using Sink = std::function<bool(const Offence&)>;

void check_indices(const Mesh& mesh, const std::string& what) {
  const long long nv = (long long)mesh.vertex_count();
  for (size_t t = 0; t < mesh.triangle_count(); ++t)
    for (int k = 0; k < 3; ++k) {
      const int32_t v = mesh.triangles[3 * t + size_t(k)];
      if (v < 0 || v >= nv)
        throw InvalidArgument(what + ": triangle " + std::to_string(t) + " names vertex " + std::to_string(v) +
                              ", which does not exist");
    }
}

bool check_points(const Mesh& mesh, const Sink& sink) {
  const size_t nv = mesh.vertex_count();
  const bool precise = mesh.precise_points.size() == 3 * nv;
  for (size_t v = 0; v < nv; ++v)
    for (size_t k = 0; k < 3; ++k) {
      const double x = precise ? mesh.precise_points[3 * v + k] : double(mesh.points[3 * v + k]);
      if (std::isfinite(x)) continue;
      Offence o;
      o.problem = "vertex " + std::to_string(v) + " has a coordinate that is not finite (NaN or infinity)";
      o.vertex = int32_t(v);
      if (!sink(o)) return false;
      break;
    }
  return true;
}

bool check_triangles(const Mesh& mesh, const Sink& sink) {
  for (size_t t = 0; t < mesh.triangle_count(); ++t) {
    const int32_t* v = &mesh.triangles[3 * t];
    if (v[0] != v[1] && v[1] != v[2] && v[2] != v[0]) continue;
    Offence o;
    o.problem = "triangle " + std::to_string(t) + " uses a vertex twice (" + std::to_string(v[0]) + ", " +
                std::to_string(v[1]) + ", " + std::to_string(v[2]) + ")";
    o.triangle = int32_t(t);
    if (!sink(o)) return false;
  }
  return true;
}

// Every undirected edge in at most two triangles, in opposite directions.
bool check_edges(const Mesh& mesh, const Sink& sink) {
  struct Edge {
    int32_t lo, hi;
    int32_t forward;  // 1 when used as lo -> hi
    int32_t face;
  };
  std::vector<Edge> edges;
  edges.reserve(mesh.triangles.size());
  for (size_t t = 0; t < mesh.triangle_count(); ++t)
    for (int k = 0; k < 3; ++k) {
      const int32_t a = mesh.triangles[3 * t + k], b = mesh.triangles[3 * t + (k + 1) % 3];
      edges.push_back({std::min(a, b), std::max(a, b), a < b ? 1 : 0, int32_t(t)});
    }
  std::sort(edges.begin(), edges.end(), [](const Edge& x, const Edge& y) {
    return x.lo != y.lo ? x.lo < y.lo : x.hi != y.hi ? x.hi < y.hi : x.face < y.face;
  });
  for (size_t i = 0; i < edges.size();) {
    size_t j = i;
    while (j < edges.size() && edges[j].lo == edges[i].lo && edges[j].hi == edges[i].hi) ++j;
    const std::string name = "edge (" + std::to_string(edges[i].lo) + ", " + std::to_string(edges[i].hi) + ")";
    Offence o;
    o.triangle = edges[i].face;
    if (j - i > 2)
      o.problem = "the mesh is not manifold: " + name + " is shared by " + std::to_string(j - i) + " triangles";
    else if (j - i == 2 && edges[i].forward == edges[i + 1].forward)
      o.problem = "the triangles are not consistently oriented: " + name + " is used in the same direction by triangles " +
                  std::to_string(edges[i].face) + " and " + std::to_string(edges[i + 1].face);
    if (!o.problem.empty() && !sink(o)) return false;
    i = j;
  }
  return true;
}

// Around each vertex the opposite edges of its triangles form one cycle or
// one path; more than one is a non-manifold vertex (two fans meeting).
bool check_vertex_fans(const Mesh& mesh, const Sink& sink) {
  const size_t nv = mesh.vertex_count(), nt = mesh.triangle_count();
  std::vector<int32_t> start(nv + 1, 0), faces(3 * nt);
  for (int32_t v : mesh.triangles) ++start[size_t(v) + 1];
  for (size_t v = 0; v < nv; ++v) start[v + 1] += start[v];
  std::vector<int32_t> fill(start.begin(), start.end() - 1);
  for (size_t t = 0; t < nt; ++t)
    for (int k = 0; k < 3; ++k) faces[size_t(fill[size_t(mesh.triangles[3 * t + k])]++)] = int32_t(t);
  std::vector<std::array<int32_t, 2>> link;
  for (size_t v = 0; v < nv; ++v) {
    link.clear();
    for (int32_t i = start[v]; i < start[v + 1]; ++i) {
      const int32_t* t = &mesh.triangles[3 * size_t(faces[size_t(i)])];
      const int k = t[0] == int32_t(v) ? 0 : t[1] == int32_t(v) ? 1 : 2;
      link.push_back({t[(k + 1) % 3], t[(k + 2) % 3]});
    }
    if (link.size() < 2) continue;
    // Walk from a path start (a source that is no target), else from any edge.
    size_t first = 0;
    for (size_t a = 0; a < link.size(); ++a) {
      bool is_target = false;
      for (const auto& e : link) is_target |= e[1] == link[a][0];
      if (!is_target) first = a;
    }
    size_t visited = 1;
    int32_t at = link[first][1];
    for (size_t step = 0; step < link.size(); ++step) {
      size_t next = link.size();
      for (size_t a = 0; a < link.size(); ++a)
        if (link[a][0] == at) next = a;
      if (next == link.size() || next == first) break;
      ++visited;
      at = link[next][1];
    }
    if (visited == link.size()) continue;
    Offence o;
    o.problem = "the mesh is not manifold at vertex " + std::to_string(v) + ": its triangles form more than one fan";
    o.vertex = int32_t(v);
    if (!sink(o)) return false;
  }
  return true;
}

std::string number(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", x);
  return text;
}

bool check_overlaps(const Mesh& mesh, const Sink& sink) {
  for (const OverlapPair& p : find_overlaps(mesh)) {
    Offence o;
    o.problem = "the mesh overlaps itself: triangles " + std::to_string(p.a) + " and " + std::to_string(p.b) +
                " intersect (near " + number(p.near[0]) + ", " + number(p.near[1]) + ", " + number(p.near[2]) + ")";
    o.triangle = p.a;
    o.other = p.b;
    if (!sink(o)) return false;
  }
  return true;
}

}  // namespace

void find_offences(const Mesh& mesh, const std::string& what, const Sink& sink) {
  check_indices(mesh, what);
  const bool go_on = check_points(mesh, sink) && check_triangles(mesh, sink) && check_edges(mesh, sink) &&
                     check_vertex_fans(mesh, sink) && check_overlaps(mesh, sink);
  (void)go_on;
}

void validate_input(const Mesh& mesh, const std::string& what) {
  find_offences(mesh, what, [&](const Offence& o) -> bool { throw InvalidArgument(what + ": " + o.problem); });
}

}  // namespace isoform::reduce

// Entry checks of the reduction (see validate.h).
#include "validate.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstdio>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

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
// The edges are grouped by their lower vertex (a counting sort), each group
// is sorted by (upper vertex, triangle) and checked in parallel, and the
// offences are then reported serially in (lower, upper) order.
struct EdgeUse {
  int32_t hi, face;
  int32_t forward;  // 1 when used as lo -> hi
  bool operator<(const EdgeUse& o) const { return hi != o.hi ? hi < o.hi : face < o.face; }
};

// The offence of the edge group [first, last) of lower vertex lo, if any.
bool edge_offence(int32_t lo, const EdgeUse* first, const EdgeUse* last, Offence* o) {
  const size_t n = size_t(last - first);
  if (n <= 1 || (n == 2 && first[0].forward != first[1].forward)) return false;
  if (o) {
    const std::string name = "edge (" + std::to_string(lo) + ", " + std::to_string(first->hi) + ")";
    o->triangle = first->face;
    if (n > 2)
      o->problem = "the mesh is not manifold: " + name + " is shared by " + std::to_string(n) + " triangles";
    else
      o->problem = "the triangles are not consistently oriented: " + name + " is used in the same direction by triangles " +
                   std::to_string(first[0].face) + " and " + std::to_string(first[1].face);
  }
  return true;
}

// Visits the groups of equal upper vertex in the sorted uses of one lower vertex.
template <class Visit>
bool for_edge_groups(const EdgeUse* first, const EdgeUse* last, Visit visit) {
  for (const EdgeUse* i = first; i != last;) {
    const EdgeUse* j = i;
    while (j != last && j->hi == i->hi) ++j;
    if (!visit(i, j)) return false;
    i = j;
  }
  return true;
}

bool check_edges(const Mesh& mesh, const Sink& sink) {
  const size_t nv = mesh.vertex_count(), nt = mesh.triangle_count();
  std::vector<size_t> start(nv + 1, 0);
  for (size_t t = 0; t < nt; ++t)
    for (int k = 0; k < 3; ++k)
      ++start[size_t(std::min(mesh.triangles[3 * t + k], mesh.triangles[3 * t + (k + 1) % 3])) + 1];
  for (size_t v = 0; v < nv; ++v) start[v + 1] += start[v];
  std::vector<size_t> fill(start.begin(), start.end() - 1);
  std::vector<EdgeUse> uses(3 * nt);
  for (size_t t = 0; t < nt; ++t)
    for (int k = 0; k < 3; ++k) {
      const int32_t a = mesh.triangles[3 * t + k], b = mesh.triangles[3 * t + (k + 1) % 3];
      uses[fill[size_t(std::min(a, b))]++] = {std::max(a, b), int32_t(t), a < b ? 1 : 0};
    }
  std::vector<uint8_t> bad(nv, 0);
  tbb::parallel_for(tbb::blocked_range<size_t>(0, nv, 4096), [&](const tbb::blocked_range<size_t>& r) {
    for (size_t v = r.begin(); v != r.end(); ++v) {
      EdgeUse* first = uses.data() + start[v];
      EdgeUse* last = uses.data() + start[v + 1];
      std::sort(first, last);
      bad[v] = !for_edge_groups(first, last, [&](const EdgeUse* i, const EdgeUse* j) {
        return !edge_offence(int32_t(v), i, j, nullptr);
      });
    }
  });
  for (size_t v = 0; v < nv; ++v) {
    if (!bad[v]) continue;
    const bool go_on = for_edge_groups(uses.data() + start[v], uses.data() + start[v + 1],
                                       [&](const EdgeUse* i, const EdgeUse* j) {
                                         Offence o;
                                         return !edge_offence(int32_t(v), i, j, &o) || sink(o);
                                       });
    if (!go_on) return false;
  }
  return true;
}

// Around each vertex the opposite edges of its triangles form one cycle or
// one path; more than one is a non-manifold vertex (two fans meeting).
// *open: a link edge starts where none ends (with one fan: a path, so the
// vertex is on the boundary).
bool one_fan(const Mesh& mesh, const int32_t* faces, size_t count, int32_t v, std::vector<std::array<int32_t, 2>>& link,
             bool* open = nullptr) {
  link.clear();
  if (open) *open = count == 1;
  for (size_t i = 0; i < count; ++i) {
    const int32_t* t = &mesh.triangles[3 * size_t(faces[i])];
    const int k = t[0] == v ? 0 : t[1] == v ? 1 : 2;
    link.push_back({t[(k + 1) % 3], t[(k + 2) % 3]});
  }
  if (link.size() < 2) return true;
  // Walk from a path start (a source that is no target), else from any edge.
  size_t first = 0;
  for (size_t a = 0; a < link.size(); ++a) {
    bool is_target = false;
    for (const auto& e : link) is_target |= e[1] == link[a][0];
    if (!is_target) {
      first = a;
      if (open) *open = true;
    }
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
  return visited == link.size();
}

// The vertices are checked in parallel, the offences reported in order.
bool check_vertex_fans(const Mesh& mesh, const VertexStars& stars, const Sink& sink) {
  const size_t nv = mesh.vertex_count();
  std::vector<uint8_t> bad(nv, 0);
  tbb::parallel_for(tbb::blocked_range<size_t>(0, nv, 4096), [&](const tbb::blocked_range<size_t>& r) {
    std::vector<std::array<int32_t, 2>> link;
    for (size_t v = r.begin(); v != r.end(); ++v) bad[v] = !one_fan(mesh, stars.begin(v), stars.size(v), int32_t(v), link);
  });
  for (size_t v = 0; v < nv; ++v) {
    if (!bad[v]) continue;
    Offence o;
    o.problem = "the mesh is not manifold at vertex " + std::to_string(v) + ": its triangles form more than one fan";
    o.vertex = int32_t(v);
    if (!sink(o)) return false;
  }
  return true;
}

// The edge and fan checks at once, from each vertex's star: its edges go
// to the corners after it and come from the corners before it, so every
// edge is in at most two triangles, in opposite directions when in two,
// exactly when around every vertex the corners after it are distinct and
// so are those before it (a triangle that uses a vertex twice lists it
// twice and fails too). True when every vertex passes; check_edges and
// check_vertex_fans then find nothing, and are run only to name the
// offenders otherwise.
// NOTE: check_edges alone builds and sorts a table of all edges; this reads
// the star table, which the working mesh's face lists are then filled from.
// With on_boundary: a flag per vertex when every vertex passes (one fan
// each, so an open link is a path: the vertex is on the boundary), else
// emptied.
bool stars_pass(const Mesh& mesh, const VertexStars& stars, std::vector<uint8_t>* on_boundary) {
  const size_t nv = mesh.vertex_count();
  std::atomic<bool> pass{true};
  if (on_boundary) on_boundary->assign(nv, 0);
  tbb::parallel_for(tbb::blocked_range<size_t>(0, nv, 4096), [&](const tbb::blocked_range<size_t>& r) {
    std::vector<std::array<int32_t, 2>> link;
    for (size_t v = r.begin(); v != r.end() && pass.load(std::memory_order_relaxed); ++v) {
      bool open = false;
      bool fine = one_fan(mesh, stars.begin(v), stars.size(v), int32_t(v), link, &open);
      for (size_t i = 0; i < link.size() && fine; ++i)
        for (size_t j = i + 1; j < link.size() && fine; ++j)
          fine = link[i][0] != link[j][0] && link[i][1] != link[j][1];
      if (!fine) pass.store(false, std::memory_order_relaxed);
      if (on_boundary) (*on_boundary)[v] = open ? 1 : 0;
    }
  });
  if (!pass.load() && on_boundary) on_boundary->clear();
  return pass.load();
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

// Every check but the overlap one, after check_indices; false when sink
// asked to stop.
bool manifold_offences(const Mesh& mesh, const VertexStars& stars, const Sink& sink,
                       std::vector<uint8_t>* on_boundary = nullptr) {
  return check_points(mesh, sink) && check_triangles(mesh, sink) &&
         (stars_pass(mesh, stars, on_boundary) || (check_edges(mesh, sink) && check_vertex_fans(mesh, stars, sink)));
}

Sink throw_first(const std::string& what) {
  return [what](const Offence& o) -> bool { throw InvalidArgument(what + ": " + o.problem); };
}

}  // namespace

void find_offences(const Mesh& mesh, const std::string& what, const Sink& sink) {
  check_indices(mesh, what);
  if (manifold_offences(mesh, vertex_stars(mesh), sink)) check_overlaps(mesh, sink);
}

void validate_manifold(const Mesh& mesh, const VertexStars& stars, const std::string& what,
                       std::vector<uint8_t>* on_boundary) {
  manifold_offences(mesh, stars, throw_first(what), on_boundary);
}

void validate_no_overlap(const Mesh& mesh, const std::string& what) { check_overlaps(mesh, throw_first(what)); }

void validate_indices(const Mesh& mesh, const std::string& what) { check_indices(mesh, what); }

void validate_input(const Mesh& mesh, const std::string& what) {
  check_indices(mesh, what);
  validate_manifold(mesh, vertex_stars(mesh), what);
  validate_no_overlap(mesh, what);
}

}  // namespace isoform::reduce

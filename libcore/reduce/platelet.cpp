// The triangle platelet, its corona and the ordered boundary polygon (see
// platelet.h), and the seed's choice of origin per kind of corona (Section
// 5.2, Figure 5.4).
#include "platelet.h"

#include "prefetch.h"

#include <algorithm>

#include <Eigen/Geometry>

namespace isoform::reduce {
namespace {

int t_vertex_slot(const Platelet& p, int v) {
  return v == p.a[0] ? 0 : v == p.a[1] ? 1 : v == p.a[2] ? 2 : -1;
}

// Link edges of the corona: ring_face holds the faces, link_from/to the edge.
struct Link {
  std::vector<int> from, to, face, neighbour_tip;
};

PlateletStatus collect_link(const WorkMesh& w, Platelet& p, Link& link) {
  for (int f : p.faces) {
    if (f == p.face) continue;
    const auto& t = w.tri[size_t(f)];
    int count = 0, slot = -1;
    for (int k = 0; k < 3; ++k)
      if (t_vertex_slot(p, t[size_t(k)]) >= 0) {
        ++count;
        slot = k;
      }
    if (count == 3) return PlateletStatus::Nonmanifold;
    if (count == 2) {
      ++p.neighbours;
      for (int k = 0; k < 3; ++k)
        if (t_vertex_slot(p, t[size_t(k)]) < 0) link.neighbour_tip.push_back(t[size_t(k)]);
      continue;
    }
    link.from.push_back(t[size_t((slot + 1) % 3)]);
    link.to.push_back(t[size_t((slot + 2) % 3)]);
    link.face.push_back(f);
  }
  return PlateletStatus::Ok;
}

// Orders the link into one cycle (closed) or one path (open), or fails.
PlateletStatus order_ring(const Link& link, Platelet& p) {
  const size_t m = link.from.size();
  if (m == 0) return PlateletStatus::Corona;
  // Each vertex at most once as a start and once as an end of an edge.
  size_t start = 0;
  int path_starts = 0;
  for (size_t i = 0; i < m; ++i) {
    int as_from = 0, as_to = 0;
    for (size_t j = 0; j < m; ++j) {
      as_from += link.from[j] == link.from[i];
      as_to += link.to[j] == link.from[i];
    }
    if (as_from > 1 || as_to > 1) return PlateletStatus::Nonmanifold;
    if (as_to == 0) {
      ++path_starts;
      start = i;
    }
  }
  if (p.closed ? path_starts != 0 : path_starts != 1) return PlateletStatus::Corona;
  size_t at = start;
  for (size_t step = 0; step < m; ++step) {
    p.ring.push_back(link.from[at]);
    p.ring_face.push_back(link.face[at]);
    size_t next = m;
    for (size_t j = 0; j < m; ++j)
      if (link.from[j] == link.to[at]) next = j;
    if (next == m) {  // the path ends
      if (p.closed || step + 1 != m) return PlateletStatus::Corona;
      p.ring.push_back(link.to[at]);
      break;
    }
    if (next == start) {
      if (!p.closed || step + 1 != m) return PlateletStatus::Corona;
      break;
    }
    at = next;
  }
  if (p.ring_face.size() != m) return PlateletStatus::Corona;
  // Every vertex next to T lies on the polygon, also the neighbours' tips.
  for (int tip : link.neighbour_tip) {
    bool found = false;
    for (int y : p.ring) found |= y == tip;
    if (!found) return PlateletStatus::Corona;
  }
  const bool big = p.closed ? p.ring.size() >= 3 : p.ring.size() >= 2;
  return big ? PlateletStatus::Ok : PlateletStatus::Corona;
}

// Section 5.2's origin c for an open corona (Figure 5.4).
void choose_open_origin(const WorkMesh& w, const Platelet& p, const Link& link, Platelet& out) {
  const auto& P = [&](int v) -> const Eigen::Vector3d& { return w.pos[size_t(v)]; };
  // A vertex of T in no other triangle.
  for (int k = 0; k < 3; ++k)
    if (w.vfaces[size_t(p.a[size_t(k)])].size() == 1) {
      out.origin_kind = 1;
      out.origin_vertex = p.a[size_t(k)];
      out.origin = P(out.origin_vertex);
      return;
    }
  if (p.neighbours == 3) {  // one vertex of T on the boundary
    for (int k = 0; k < 3; ++k)
      if (p.open_vertex[k]) {
        out.origin_kind = 1;
        out.origin_vertex = p.a[size_t(k)];
        out.origin = P(out.origin_vertex);
        return;
      }
  }
  // Two neighbours: T's edge without a neighbour is a boundary edge.
  int e0 = -1, e1 = -1;
  for (int k = 0; k < 3; ++k) {
    const int u = p.a[size_t(k)], v = p.a[size_t((k + 1) % 3)];
    bool has = false;
    for (int f : p.faces)
      if (f != p.face && w.face_with_vertex_index(f, u) >= 0 && w.face_with_vertex_index(f, v) >= 0) has = true;
    if (!has) {
      e0 = u;
      e1 = v;
    }
  }
  auto tip_is_neighbour = [&](int y) {
    for (int tip : link.neighbour_tip)
      if (tip == y) return true;
    return false;
  };
  const bool first = tip_is_neighbour(p.ring.front()), last = tip_is_neighbour(p.ring.back());
  if (e0 >= 0 && first != last) {
    // The vertex shared only by T and the first (last) triangle: the end of
    // the boundary edge that lies in two triangles.
    for (int v : {e0, e1})
      if (w.vfaces[size_t(v)].size() == 2) {
        out.origin_kind = 1;
        out.origin_vertex = v;
        out.origin = P(v);
        return;
      }
  }
  if (e0 >= 0) {
    out.origin_kind = 2;
    out.origin = 0.5 * (P(e0) + P(e1));
    return;
  }
  out.origin_kind = 0;
  out.origin = (P(p.a[0]) + P(p.a[1]) + P(p.a[2])) / 3.0;
}

}  // namespace

PlateletStatus gather_platelet(const WorkMesh& w, int face, Platelet& p) {
  p.face = face;
  p.a = w.tri[size_t(face)];
  p.faces.clear();
  p.ring.clear();
  p.ring_face.clear();
  p.neighbours = 0;
  p.origin_kind = 0;
  p.origin_vertex = -1;
  // NOTE: the faces around T's vertices, each once: sorted and made unique
  // here rather than marked in a per-face array (one more cache line per
  // face, read and written in the queue's order all over memory).
  for (int k = 0; k < 3; ++k) prefetch(&w.pos[size_t(p.a[size_t(k)])]);
  for (int k = 0; k < 3; ++k) {
    p.open_vertex[k] = w.boundary[size_t(p.a[size_t(k)])] != 0;
    for (int f : w.vfaces[size_t(p.a[size_t(k)])]) {
      prefetch(&w.tri[size_t(f)]);
      p.faces.push_back(f);
    }
  }
  std::sort(p.faces.begin(), p.faces.end());
  p.faces.erase(std::unique(p.faces.begin(), p.faces.end()), p.faces.end());
  p.closed = !p.open_vertex[0] && !p.open_vertex[1] && !p.open_vertex[2];
  static thread_local Link link;
  link.from.clear();
  link.to.clear();
  link.face.clear();
  link.neighbour_tip.clear();
  if (collect_link(w, p, link) != PlateletStatus::Ok) return PlateletStatus::Nonmanifold;
  const PlateletStatus ordered = order_ring(link, p);
  if (ordered != PlateletStatus::Ok) return ordered;
  if (p.closed)
    p.origin = (w.pos[size_t(p.a[0])] + w.pos[size_t(p.a[1])] + w.pos[size_t(p.a[2])]) / 3.0;
  else
    choose_open_origin(w, p, link, p);
  return PlateletStatus::Ok;
}

}  // namespace isoform::reduce

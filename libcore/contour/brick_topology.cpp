// Neighbours and parts inside one brick (Hamann 1991, Algorithms 3.1, 3.2).
#include "brick_topology.h"

#include <algorithm>
#include <climits>
#include <cstddef>
#include <stdexcept>

namespace isoform {
namespace {

int next(int i) { return i == 2 ? 0 : i + 1; }

// Does triangle edge e (3 t + i) run from its smaller vertex to its larger?
bool runs_up(const int32_t* tris, int32_t e) {
  const int32_t t = e / 3;
  return tris[e] < tris[3 * t + next(e - 3 * t)];
}

}  // namespace

int32_t BrickTopology::run(const int32_t* tris, const uint8_t* links, bool reversed, size_t nt,
                           size_t vertex_count, const uint8_t* shared, const int32_t* final_vertex,
                           int64_t first_triangle, int32_t* neighbours, int32_t* parts, TopologyCounts& total,
                           SeamEdge* seams, size_t seam_count) {
  SeamEdge* const seams_end = seams + seam_count;
  TopologyCounts counts;  // local, so that it stays in registers
  // Swapping a triangle's last two vertices turns its edge i into edge 2 - i.
  const auto oriented = [&](int e) { return reversed ? 2 - e : e; };
  // The triangle edges of each undirected local edge, grouped under its
  // smaller vertex: a short list per vertex (its sides on the few cell faces
  // around its grid edge, and a spoke), the groups kept in the order their
  // edges are first met. compute_neighbours finds the same groups by its
  // vertex scan. Fan links pair the edges inside a fan directly (below).
  if (first_.size() < vertex_count) first_.resize(vertex_count);
  std::fill(first_.begin(), first_.begin() + std::ptrdiff_t(vertex_count), -1);
  // At most one group per triangle edge: the array is sized once and
  // filled by count.
  if (groups_.size() < 3 * nt) groups_.resize(3 * nt);
  size_t group_count = 0;
  for (size_t t = 0; t < nt; ++t) {
    int linked = 0;
    if (links[t]) linked |= 1 << oriented(links[t] & 3);
    if (t > 0 && links[t - 1]) linked |= 1 << oriented((links[t - 1] >> 2) & 3);
    for (int e = 0; e < 3; ++e) {
      if ((linked >> e) & 1) continue;
      const size_t at = 3 * t + size_t(e);
      const int32_t a = tris[at], b = tris[3 * t + size_t(next(e))];
      neighbours[at] = -1;
      if (shared[a] && shared[b]) {
        const uint64_t fa = uint64_t(final_vertex[a]), fb = uint64_t(final_vertex[b]);
        if (seams == seams_end) throw std::logic_error("contour: more seam edges than the brick counted");
        *seams++ = {fa < fb ? (fa << 32) | fb : (fb << 32) | fa,
                    (uint64_t(3 * first_triangle) + at) << 1 | uint64_t(fa < fb)};
        continue;
      }
      const int32_t lo = std::min(a, b), hi = std::max(a, b);
      int32_t g = first_[size_t(lo)];
      while (g >= 0 && groups_[size_t(g)].other != hi) g = groups_[size_t(g)].next;
      if (g < 0) {
        // NOTE: the fields are stored one by one: a Group built first and
        // copied in is read back as one 16-byte load from four 4-byte
        // stores, which the core cannot forward (a stall of its own).
        const size_t n = group_count++;
        Group& fresh = groups_[n];
        fresh.other = hi;
        fresh.first = int32_t(at);
        fresh.second = -1;
        fresh.next = first_[size_t(lo)];
        first_[size_t(lo)] = int32_t(n);
      } else {
        Group& group = groups_[size_t(g)];
        group.second = group.second == -1 ? int32_t(at) : kMore;
      }
    }
  }
  start_parts(links, nt);
  for (size_t k = 0; k < group_count; ++k) {
    const Group& slot = groups_[k];
    ++counts.edges;
    if (slot.second == -1) {
      ++counts.boundary;
    } else if (slot.second >= 0) {
      const int32_t t = slot.first / 3, u = slot.second / 3;
      neighbours[size_t(slot.first)] = int32_t(first_triangle) + u;
      neighbours[size_t(slot.second)] = int32_t(first_triangle) + t;
      counts.inconsistent += runs_up(tris, slot.first) == runs_up(tris, slot.second);
      join(t, u);
    } else {
      ++counts.nonmanifold;
    }
  }
  link_fans(tris, links, reversed, nt, first_triangle, neighbours, counts);
  if (seams != seams_end) throw std::logic_error("contour: fewer seam edges than the brick counted");
  total.add(counts);
  return number_parts(nt, parts);
}

int32_t BrickTopology::run_paired(const int32_t* tris, const uint8_t* links, bool reversed, size_t nt,
                                  const BrickSides& sides, const int32_t* final_vertex, int64_t first_triangle,
                                  int32_t* neighbours, int32_t* parts, TopologyCounts& total, SeamEdge* seams,
                                  size_t seam_count) {
  TopologyCounts counts;
  // Edges are numbered as the contour wrote them; swapping a triangle's
  // last two vertices turns its edge i into edge 2 - i.
  const auto oriented = [&](uint32_t e) {
    const uint32_t i = e % 3;
    return int32_t(e - i + (reversed ? 2 - i : i));
  };
  std::fill(neighbours, neighbours + 3 * nt, -1);
  for (size_t m = 0; m < seam_count; ++m) {
    const int32_t at = oriented(sides.seam[m]), t = at / 3;
    const uint64_t fa = uint64_t(final_vertex[tris[at]]), fb = uint64_t(final_vertex[tris[3 * t + next(at - 3 * t)]]);
    seams[m] = {fa < fb ? (fa << 32) | fb : (fb << 32) | fa,
                (uint64_t(3 * first_triangle) + uint64_t(at)) << 1 | uint64_t(fa < fb)};
  }
  start_parts(links, nt);
  for (size_t m = 0; m < sides.pair_count; ++m) {
    const int32_t a = oriented(sides.pairs[2 * m]), b = oriented(sides.pairs[2 * m + 1]);
    const int32_t t = a / 3, u = b / 3;
    neighbours[a] = int32_t(first_triangle) + u;
    neighbours[b] = int32_t(first_triangle) + t;
    counts.inconsistent += runs_up(tris, a) == runs_up(tris, b);
    join(t, u);
  }
  counts.edges += (long long)sides.pair_count + (long long)sides.lone_count;
  counts.boundary += (long long)sides.lone_count;
  link_fans(tris, links, reversed, nt, first_triangle, neighbours, counts);
  total.add(counts);
  return number_parts(nt, parts);
}

void BrickTopology::start_parts(const uint8_t* links, size_t nt) {
  // The triangles of one fan start joined under its first triangle (fan
  // links join them anyway): the smallest of their part, as every root is,
  // so the links need no find.
  root_.resize(nt);
  for (size_t t = 0; t < nt; ++t) root_[t] = t > 0 && links[t - 1] ? root_[t - 1] : int32_t(t);
}

void BrickTopology::link_fans(const int32_t* tris, const uint8_t* links, bool reversed, size_t nt,
                              int64_t first_triangle, int32_t* neighbours, TopologyCounts& counts) const {
  const auto oriented = [&](int e) { return reversed ? 2 - e : e; };
  for (size_t t = 0; t + 1 < nt; ++t) {
    if (!links[t]) continue;
    const int32_t here = int32_t(3 * t) + oriented(links[t] & 3);
    const int32_t there = int32_t(3 * t + 3) + oriented((links[t] >> 2) & 3);
    ++counts.edges;
    neighbours[here] = int32_t(first_triangle) + int32_t(t) + 1;
    neighbours[there] = int32_t(first_triangle) + int32_t(t);
    counts.inconsistent += runs_up(tris, here) == runs_up(tris, there);
  }
}

int32_t BrickTopology::number_parts(size_t nt, int32_t* parts) {
  // Every link points to a smaller triangle (join, start_parts), so the
  // triangle a non-root points to is numbered already, with its root's
  // label: no find.
  int32_t label = 0;
  for (size_t t = 0; t < nt; ++t) {
    const int32_t r = root_[t];
    parts[t] = size_t(r) == t ? label++ : parts[size_t(r)];
  }
  return label;
}

}  // namespace isoform

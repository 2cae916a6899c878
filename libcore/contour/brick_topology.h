// Section 3.3's neighbour table and parts, computed brick by brick.
//
// Every triangle lies in one cell, and an edge of it joins two crossings of
// that cell (or a crossing and the cell's extra point). A vertex that no
// other brick shares is used by this brick's triangles only, so every edge
// with such an end has all its triangles here: its neighbours are found in
// the brick's own small vertex-to-triangle table. Only edges whose two ends
// are both shared (they lie on the brick's boundary) can have triangles in
// other bricks; they become SeamEdge records, matched globally (seams.h).
// The result is the same table compute_neighbours (topology.h) gives.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "brick_contour.h"

namespace isoform {

// One triangle edge whose two vertices are both on brick boundaries.
struct SeamEdge {
  uint64_t key;   // (smaller final vertex << 32) | larger final vertex
  // (3 * global triangle + i) << 1 | up: the edge (v_i, v_i+1), up when
  // v_i is the smaller vertex (what the inconsistency count needs).
  uint64_t edge;
  uint64_t triangle_edge() const { return edge >> 1; }
  bool runs_up() const { return edge & 1; }
};

inline bool operator<(const SeamEdge& a, const SeamEdge& b) {
  return a.key != b.key ? a.key < b.key : a.edge < b.edge;
}

// Edge counts for MeshStats, summed over bricks and seams.
struct TopologyCounts {
  long long boundary = 0, nonmanifold = 0, inconsistent = 0, degenerate = 0, edges = 0;
  void add(const TopologyCounts& o) {
    boundary += o.boundary;
    nonmanifold += o.nonmanifold;
    inconsistent += o.inconsistent;
    degenerate += o.degenerate;
    edges += o.edges;
  }
};

// Per-thread scratch for the local topology of one brick at a time.
class BrickTopology {
 public:
  // tris: the brick's oriented triangles over local vertices; links: their
  // fan links (brick_contour.h), edges numbered as the contour wrote them
  // (reversed: tris has each triangle's last two vertices swapped since);
  // vertex_count: the brick's local vertices; shared: 1 per local vertex
  // that other bricks may use; final_vertex: the final index of each local
  // vertex; first_triangle: the global index of the brick's triangle 0.
  // Writes the neighbours of local edges into neighbours (3 per triangle;
  // seam edges are left for seams.h), writes the seam edges to seams
  // (exactly seam_count of them, BrickMesh::seam_count: std::logic_error
  // otherwise), and writes into parts the brick-local part of each
  // triangle over local edges (numbered by first triangle). Returns the
  // number of local parts.
  int32_t run(const int32_t* tris, const uint8_t* links, bool reversed, size_t nt, size_t vertex_count,
              const uint8_t* shared, const int32_t* final_vertex, int64_t first_triangle, int32_t* neighbours,
              int32_t* parts, TopologyCounts& counts, SeamEdge* seams, size_t seam_count);
  // The same for the cell method, whose contour paired the edges that no
  // fan link covers itself (BrickSides, brick_contour.h): no lookup.
  int32_t run_paired(const int32_t* tris, const uint8_t* links, bool reversed, size_t nt, const BrickSides& sides,
                     const int32_t* final_vertex, int64_t first_triangle, int32_t* neighbours, int32_t* parts,
                     TopologyCounts& counts, SeamEdge* seams, size_t seam_count);

 private:
  // One undirected local edge, listed under its smaller vertex: the larger
  // vertex, its first two triangle edges (second is -1 while it has one,
  // kMore once it has more than two) and the next edge of the same list.
  struct Group {
    int32_t other, first, second, next;
  };
  static constexpr int32_t kMore = -2;

  // The triangles of each fan in one part under its first triangle.
  void start_parts(const uint8_t* links, size_t nt);
  // The neighbours across the fans' inner edges (fan links).
  void link_fans(const int32_t* tris, const uint8_t* links, bool reversed, size_t nt, int64_t first_triangle,
                 int32_t* neighbours, TopologyCounts& counts) const;
  int32_t find(int32_t x) {
    while (root_[size_t(x)] != x) x = root_[size_t(x)] = root_[size_t(root_[size_t(x)])];
    return x;
  }
  void join(int32_t t, int32_t u) {
    const int32_t ra = find(t), rb = find(u);
    if (ra != rb) root_[size_t(std::max(ra, rb))] = std::min(ra, rb);
  }
  // Roots are the smallest triangle of their part: numbers them in order.
  int32_t number_parts(size_t nt, int32_t* parts);

  std::vector<int32_t> first_;  // per local vertex: its list's first group, or -1
  std::vector<Group> groups_;   // in the order the edges are first met
  std::vector<int32_t> root_;
};

}  // namespace isoform

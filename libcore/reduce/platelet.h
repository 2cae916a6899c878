// Section 5.1 of Hamann (1991): the triangle platelet of T (every triangle
// sharing a vertex with T, Definition 5.1), its corona (5.2), the corona's
// continuity, acyclicity and closedness (Definitions 5.3-5.5), and the
// ordered counter-clockwise boundary vertex set (Theorem 5.2, Definition 5.8).
//
// NOTE: the corona is read through its link: each corona triangle with one
// vertex of T contributes the directed edge opposite that vertex; the two-
// vertex ones are T's edge neighbours and vanish with T. The corona is
// continuous and acyclic exactly when these edges form one simple cycle
// (closed corona) or one simple path (open corona) through every vertex next
// to T; then contracting T leaves a manifold, and the orientation of the
// triangles orders the polygon counter-clockwise (Definition 5.8) directly.
#pragma once

#include <algorithm>
#include <array>
#include <vector>

#include <Eigen/Core>

#include "work_mesh.h"

namespace isoform::reduce {

// Corona: discontinuous, cyclic or too small; Nonmanifold: contracting T
// would give an edge three triangles or a duplicate triangle.
enum class PlateletStatus { Ok, Corona, Nonmanifold };

struct Platelet {
  int face = -1;
  std::array<int, 3> a{};              // T's vertices, counter-clockwise
  std::vector<int> faces;              // T and its corona, ascending ids
  std::vector<int> ring;               // B_ord: y_0 .. y_n, counter-clockwise
  std::vector<int> ring_face;          // corona face giving edge y_j -> y_j+1
  bool closed = false;                 // Definition 5.5
  int neighbours = 0;                  // T's edges with a triangle across
  bool open_vertex[3] = {false, false, false};  // T vertex on the mesh boundary
  Eigen::Vector3d origin{0, 0, 0};     // c of Section 5.2 for this corona kind
  int origin_kind = 0;                 // 0 centroid, 1 vertex, 2 edge mid-point
  int origin_vertex = -1;              // the vertex, kind 1

  int link_edges() const { return int(ring_face.size()); }
};

// Gathers T's platelet into p (reusing its storage).
PlateletStatus gather_platelet(const WorkMesh& w, int face, Platelet& p);

// Is face f one of the platelet's (T or its corona)?
inline bool in_platelet(const Platelet& p, int f) { return std::binary_search(p.faces.begin(), p.faces.end(), f); }

}  // namespace isoform::reduce

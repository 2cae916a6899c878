// The local re-triangulation of Section 5.2 of Hamann (1991): the fan from
// the new point p to the ordered boundary polygon (5.40), then Lawson-like
// diagonal swaps that raise the smaller angle weight of the two triangles of
// a quadrilateral, made only where the quadrilateral's projection onto T's
// plane is convex (Definition 5.15) and the new diagonal is not an edge yet.
#pragma once

#include <array>
#include <vector>

#include "platelet.h"
#include "replacement.h"

namespace isoform::reduce {

struct LocalFaces {
  std::vector<std::array<int, 3>> tri;  // p is the vertex p.a[0] (it inherits its index)
  std::vector<int> source;              // the corona face a fan face replaces; -1 after a swap
};

// The position of vertex v once p has replaced T.
inline const Eigen::Vector3d& local_pos(const WorkMesh& w, const Platelet& p, const Eigen::Vector3d& point, int v) {
  return v == p.a[0] ? point : w.pos[size_t(v)];
}

void build_fan(const Platelet& p, LocalFaces& out);

// Swaps while they help; returns how many were made. Edges of the
// platelet's faces do not count (they are replaced).
int lawson_swaps(const WorkMesh& w, const Platelet& p, const Frame& frame, const Eigen::Vector3d& point,
                 LocalFaces& faces);

}  // namespace isoform::reduce

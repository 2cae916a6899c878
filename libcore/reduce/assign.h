// Which new face an original vertex belongs to, for the error tracking of
// the reduction (tracker.h): the face of the platelet's re-triangulation
// whose projection contains the vertex's projection, or comes nearest to
// containing it (the largest smallest barycentric coordinate). Graphs
// project along z onto (x, y); other surfaces onto the removed triangle's
// plane P, which the new faces cover without overlap (the half-plane test,
// with its one turn around p, and the convex swaps keep the projected
// polygon a triangulation: half_plane.h).
//
// NOTE: cheaper than the nearest face by 3D distance, which it replaces when
// no distance tolerance asks for the tightest bound: a few multiplications
// per face instead of a closest-point computation.
#pragma once

#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include <Eigen/Core>

#include "replacement.h"

namespace isoform::reduce {

// The affine map of one projected face to its barycentric coordinates.
struct ProjectedFace {
  double ox = 0, oy = 0, m00 = 0, m01 = 0, m10 = 0, m11 = 0;
  bool ok = false;

  void set(double ax, double ay, double bx, double by, double cx, double cy) {
    const double det = (bx - ax) * (cy - ay) - (cx - ax) * (by - ay);
    ok = std::abs(det) > 0;
    if (!ok) return;
    const double inv = 1.0 / det;
    ox = ax;
    oy = ay;
    m00 = (cy - ay) * inv;
    m01 = -(cx - ax) * inv;
    m10 = -(by - ay) * inv;
    m11 = (bx - ax) * inv;
  }
  // Barycentric coordinates (l0, l1, l2) of (x, y); their minimum is returned.
  double inside(double x, double y, double* l) const {
    if (!ok) return -std::numeric_limits<double>::infinity();
    const double dx = x - ox, dy = y - oy;
    l[1] = m00 * dx + m01 * dy;
    l[2] = m10 * dx + m11 * dy;
    l[0] = 1 - l[1] - l[2];
    return std::min(l[0], std::min(l[1], l[2]));
  }
};

// The projection: (x, y) for graphs, T's frame (u, v) otherwise.
struct Projection {
  const Frame* frame = nullptr;  // null: graph
  Eigen::Vector2d operator()(const Eigen::Vector3d& x) const {
    return frame ? frame->uv(x) : Eigen::Vector2d(x(0), x(1));
  }
};

// The projected faces of `tri` (positions by pos(v)), reusing out's storage.
template <class Pos>
void project_faces(const std::vector<std::array<int, 3>>& tri, const Projection& proj, Pos&& pos,
                   std::vector<ProjectedFace>& out) {
  out.resize(tri.size());
  for (size_t i = 0; i < tri.size(); ++i) {
    const Eigen::Vector2d a = proj(pos(tri[i][0])), b = proj(pos(tri[i][1])), c = proj(pos(tri[i][2]));
    out[i].set(a(0), a(1), b(0), b(1), c(0), c(1));
  }
}

// The face x projects into (or nearest to), and its barycentric coordinates.
// The projected faces do not overlap, so a face holding x with every
// barycentric coordinate clear of rounding is the one a scan for the
// largest smallest coordinate would choose: `hint` (a face index, or -1) is
// tried first, and the scan stops at such a face.
inline int containing_face(const std::vector<ProjectedFace>& faces, const Eigen::Vector2d& x, double* l,
                           int hint = -1) {
  constexpr double kClear = 1e-9;
  double best = -std::numeric_limits<double>::infinity(), tmp[3];
  if (hint >= 0 && size_t(hint) < faces.size() && faces[size_t(hint)].inside(x(0), x(1), l) > kClear) return hint;
  int chosen = 0;
  l[0] = 1;
  l[1] = l[2] = 0;
  for (size_t i = 0; i < faces.size(); ++i) {
    const double s = faces[i].inside(x(0), x(1), tmp);
    if (s > kClear) {
      l[0] = tmp[0];
      l[1] = tmp[1];
      l[2] = tmp[2];
      return int(i);
    }
    if (s > best) {
      best = s;
      chosen = int(i);
      l[0] = tmp[0];
      l[1] = tmp[1];
      l[2] = tmp[2];
    }
  }
  return chosen;
}

}  // namespace isoform::reduce

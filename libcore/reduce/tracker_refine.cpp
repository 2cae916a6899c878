// The refined point of the reduction (Tracker::refine, see tracker.h).
#include <algorithm>

#include <Eigen/Geometry>
#include <cmath>
#include <limits>

#include "tracker.h"

namespace isoform::reduce {
namespace {

// The new face nearest to x in 3D (degenerate faces never), the first of equals.
template <class Pos>
int nearest_face(const LocalFaces& faces, const Eigen::Vector3d& x, Pos&& P) {
  double best = std::numeric_limits<double>::infinity();
  int chosen = 0;
  for (size_t i = 0; i < faces.tri.size(); ++i) {
    const auto& t = faces.tri[i];
    const Eigen::Vector3d &a = P(t[0]), &b = P(t[1]), &c = P(t[2]);
    if (!((b - a).cross(c - a).squaredNorm() > 0)) continue;
    const double d = point_triangle_distance(x, a, b, c);
    if (d < best) {
      best = d;
      chosen = int(i);
    }
  }
  return chosen;
}

}  // namespace

void Tracker::refine(const WorkMesh& w, const Platelet& p, const Frame& frame, const LocalFaces& faces,
                     const Eigen::Vector3d& direction, Eigen::Vector3d& point, TrackerPending& out) const {
  const int pv = p.a[0];
  auto P = [&](int v) -> const Eigen::Vector3d& { return local_pos(w, p, point, v); };
  const bool graph = rms_ > 0, nearest = !graph && std::isfinite(distance_);
  Projection projection;
  if (!graph) projection.frame = &frame;
  if (!nearest) project_faces(faces.tri, projection, P, out.projected);
  double num = 0, den = 0, largest = 0;
  int hint = -1;  // the last vertex's face: the next one is mostly in it too
  // NOTE: the lists are read in weight order, all over memory: their first
  // entries are asked for together before the walk (only timing depends on it).
  for (int f : p.faces) {
    const int v = head_[size_t(f)];
    if (v < 0) continue;
    prefetch(&original_[size_t(v)]);
    prefetch(&next_[size_t(v)]);
  }
  // What each new face gives every vertex handed to it (surfaces): its
  // unit normal, its doubled area and where p is among its corners.
  out.face_normals.resize(graph ? 0 : faces.tri.size());
  for (size_t i = 0; i < out.face_normals.size(); ++i) {
    const auto& t = faces.tri[i];
    FaceNormal& fn = out.face_normals[i];
    const Eigen::Vector3d nn = (P(t[1]) - P(t[0])).cross(P(t[2]) - P(t[0]));
    const double area2 = nn.squaredNorm();
    fn.length = area2 > 0 ? std::sqrt(area2) : 0.0;
    if (fn.length > 0) fn.n = nn / fn.length;
  }
  out.assigned.clear();
  out.assigned_valid = true;
  list_vertices(p, out.vertex);
  const size_t n = out.vertex.size();
  for (size_t i = 0; i < std::min(n, kRecordsAhead); ++i) prefetch(&original_[size_t(out.vertex[i])]);
  for (size_t i = 0; i < n; ++i) {
    if (i + kRecordsAhead < n) prefetch(&original_[size_t(out.vertex[i + kRecordsAhead])]);
    const Eigen::Vector3d& x = original_[size_t(out.vertex[i])].x;
    // The new face x lies on (graph: above; under a distance tolerance: the
    // nearest; else: the one its projection onto P falls in) and x's
    // barycentric weight of p there.
    double l[3] = {1, 0, 0};
    const int chosen = nearest ? nearest_face(faces, x, P) : containing_face(out.projected, projection(x), l, hint);
    hint = chosen;
    out.assigned.push_back(chosen);
    const auto& t = faces.tri[size_t(chosen)];
    const int k = t[0] == pv ? 0 : t[1] == pv ? 1 : t[2] == pv ? 2 : -1;
    double weight = 0, residual = 0, slope = 0;
    if (graph) {
      weight = k >= 0 ? l[k] : 0;
      residual = x(2) - (l[0] * P(t[0])(2) + l[1] * P(t[1])(2) + l[2] * P(t[2])(2));
      slope = weight * direction(2);
    } else {
      const FaceNormal& fn = out.face_normals[size_t(chosen)];
      if (!(fn.length > 0)) continue;
      if (k >= 0) {
        const Eigen::Vector3d& y1 = P(t[size_t((k + 1) % 3)]);
        const Eigen::Vector3d opp = (P(t[size_t((k + 2) % 3)]) - y1).cross(x - y1);
        weight = std::clamp(opp.dot(fn.n) / fn.length, 0.0, 1.0);
      }
      residual = (x - P(t[0])).dot(fn.n);
      slope = weight * direction.dot(fn.n);
    }
    if (weight <= 0) continue;
    num += slope * residual;
    den += slope * slope;
    largest = std::max(largest, std::abs(residual));
  }
  // NOTE: points far from p (small weights) alone make the step ill-posed:
  // no step below the weight of one point at p's half-way, and none longer
  // than twice the largest residual.
  if (!(den >= 0.25)) return;
  point += std::clamp(num / den, -2 * largest, 2 * largest) * direction;
}

}  // namespace isoform::reduce

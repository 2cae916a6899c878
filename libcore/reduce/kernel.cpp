// The kernel of the platelet polygon (see kernel.h).
#include "kernel.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace isoform::reduce {

// NOTE: the kernel is cut out of a box around the polygon, one edge's
// half-plane at a time (each cut of a convex polygon by a half-plane is
// convex): O(n^2) for n edges, a dozen on a platelet.
std::vector<Eigen::Vector2d> polygon_kernel(const std::vector<Eigen::Vector2d>& ring, double margin) {
  const size_t n = ring.size();
  if (n < 3) return {};
  Eigen::Vector2d lo = ring[0], hi = ring[0];
  for (const Eigen::Vector2d& x : ring) {
    lo = lo.cwiseMin(x);
    hi = hi.cwiseMax(x);
  }
  std::vector<Eigen::Vector2d> kernel{lo, {hi(0), lo(1)}, hi, {lo(0), hi(1)}}, cut;
  for (size_t j = 0; j < n && !kernel.empty(); ++j) {
    const Eigen::Vector2d a = ring[j], d = ring[(j + 1) % n] - a;
    const double length = d.norm();
    if (!(length > 0)) return {};
    // Signed distance to the left of the edge, less the margin.
    const auto left = [&](const Eigen::Vector2d& x) { return (d(0) * (x(1) - a(1)) - d(1) * (x(0) - a(0))) / length - margin * length; };
    cut.clear();
    for (size_t k = 0; k < kernel.size(); ++k) {
      const Eigen::Vector2d &x = kernel[k], &y = kernel[(k + 1) % kernel.size()];
      const double sx = left(x), sy = left(y);
      if (sx > 0) cut.push_back(x);
      if ((sx > 0) != (sy > 0)) cut.push_back(x + (y - x) * (sx / (sx - sy)));
    }
    kernel.swap(cut);
  }
  if (kernel.size() < 3) return {};
  return kernel;
}

// By its triangles from the first corner.
std::optional<Eigen::Vector2d> convex_centroid(const std::vector<Eigen::Vector2d>& polygon) {
  double area = 0;
  Eigen::Vector2d sum(0, 0);
  for (size_t k = 1; k + 1 < polygon.size(); ++k) {
    const Eigen::Vector2d u = polygon[k] - polygon[0], v = polygon[k + 1] - polygon[0];
    const double a = u(0) * v(1) - u(1) * v(0);
    area += a;
    sum += a * (polygon[0] + polygon[k] + polygon[k + 1]) / 3.0;
  }
  if (!(area > 0)) return std::nullopt;
  const Eigen::Vector2d c = sum / area;
  if (!c.allFinite()) return std::nullopt;
  return c;
}

std::optional<Eigen::Vector2d> kernel_centroid(const std::vector<Eigen::Vector2d>& ring, double margin) {
  return convex_centroid(polygon_kernel(ring, margin));
}

std::optional<Eigen::Vector2d> kernel_point(const std::vector<Eigen::Vector2d>& ring, double margin,
                                            const Eigen::Vector2d& q) {
  const std::vector<Eigen::Vector2d> kernel = polygon_kernel(ring, margin);
  const std::optional<Eigen::Vector2d> centre = convex_centroid(kernel);
  if (!centre) return std::nullopt;
  bool inside = true;
  double best = std::numeric_limits<double>::infinity();
  Eigen::Vector2d nearest = *centre;
  for (size_t k = 0; k < kernel.size(); ++k) {
    const Eigen::Vector2d a = kernel[k], d = kernel[(k + 1) % kernel.size()] - a;
    inside &= d(0) * (q(1) - a(1)) - d(1) * (q(0) - a(0)) >= 0;
    const double t = std::clamp((q - a).dot(d) / d.squaredNorm(), 0.0, 1.0);
    const Eigen::Vector2d x = a + t * d;
    if ((x - q).squaredNorm() < best) {
      best = (x - q).squaredNorm();
      nearest = x;
    }
  }
  if (inside) return centre;
  const Eigen::Vector2d x = nearest + 0.25 * (*centre - nearest);
  if (!x.allFinite()) return centre;
  return x;
}

}  // namespace isoform::reduce

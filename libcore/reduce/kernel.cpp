// The kernel of the platelet polygon (see kernel.h).
#include "kernel.h"

#include <cmath>

namespace isoform::reduce {

// NOTE: the kernel is cut out of a box around the polygon, one edge's
// half-plane at a time (each cut of a convex polygon by a half-plane is
// convex): O(n^2) for n edges, a dozen on a platelet.
std::optional<Eigen::Vector2d> kernel_centroid(const std::vector<Eigen::Vector2d>& ring, double margin) {
  const size_t n = ring.size();
  if (n < 3) return std::nullopt;
  Eigen::Vector2d lo = ring[0], hi = ring[0];
  for (const Eigen::Vector2d& x : ring) {
    lo = lo.cwiseMin(x);
    hi = hi.cwiseMax(x);
  }
  std::vector<Eigen::Vector2d> kernel{lo, {hi(0), lo(1)}, hi, {lo(0), hi(1)}}, cut;
  for (size_t j = 0; j < n && !kernel.empty(); ++j) {
    const Eigen::Vector2d a = ring[j], d = ring[(j + 1) % n] - a;
    const double length = d.norm();
    if (!(length > 0)) return std::nullopt;
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
  if (kernel.size() < 3) return std::nullopt;
  // The centroid of the convex kernel by its triangles from the first corner.
  double area = 0;
  Eigen::Vector2d sum(0, 0);
  for (size_t k = 1; k + 1 < kernel.size(); ++k) {
    const Eigen::Vector2d u = kernel[k] - kernel[0], v = kernel[k + 1] - kernel[0];
    const double a = u(0) * v(1) - u(1) * v(0);
    area += a;
    sum += a * (kernel[0] + kernel[k] + kernel[k + 1]) / 3.0;
  }
  if (!(area > 0)) return std::nullopt;
  const Eigen::Vector2d c = sum / area;
  if (!c.allFinite()) return std::nullopt;
  return c;
}

}  // namespace isoform::reduce

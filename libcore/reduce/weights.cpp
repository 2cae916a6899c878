// The angle weight (5.21).
#include "weights.h"

#include <algorithm>

#include <Eigen/Geometry>

namespace isoform::reduce {

double angle_weight(const Eigen::Vector3d& x0, const Eigen::Vector3d& x1, const Eigen::Vector3d& x2) {
  const Eigen::Vector3d e0 = x1 - x0, e1 = x2 - x1, e2 = x0 - x2;
  const double l0 = e0.norm(), l1 = e1.norm(), l2 = e2.norm();
  if (!(l0 > 0 && l1 > 0 && l2 > 0)) return 0.0;
  // cos of the interior angle at each vertex, from its two edges.
  const double c0 = -e2.dot(e0) / (l2 * l0), c1 = -e0.dot(e1) / (l0 * l1), c2 = -e1.dot(e2) / (l1 * l2);
  return std::clamp(2.0 * (c0 + c1 + c2 - 1.0), 0.0, 1.0);
}

}  // namespace isoform::reduce

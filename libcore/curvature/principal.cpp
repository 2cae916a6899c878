// Principal curvatures of a height-field graph from its first and second
// fundamental forms (4.14, 4.15).
#include "principal.h"

namespace isoform {

PrincipalCurvatures principal_curvatures(const HeightFit& f, const Eigen::Vector3d& b1,
                                         const Eigen::Vector3d& b2, const Eigen::Vector3d& n) {
  return principal_curvatures_inline(f, b1, b2, n);
}

}  // namespace isoform

// Whether a mesh's points must be written in double (see formats.h).
#include <algorithm>
#include <cmath>

#include "formats.h"

namespace isoform::meshio {

bool points_need_double(const Mesh& mesh) {
  const std::vector<double>& p = mesh.precise_points;
  if (p.empty() || p.size() != mesh.points.size()) return false;
  double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY}, moved = 0;
  for (size_t i = 0; i < p.size(); ++i) {
    lo[i % 3] = std::min(lo[i % 3], p[i]);
    hi[i % 3] = std::max(hi[i % 3], p[i]);
    moved = std::max(moved, std::fabs(p[i] - double(float(p[i]))));
  }
  const double extent = std::hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]);
  return moved > 1e-6 * extent;
}

}  // namespace isoform::meshio

// The domain's world mapping and the trilinear sampler.
#include "domain.h"

#include <algorithm>
#include <cmath>

#include "../errors.h"

namespace isoform::visualize {
namespace {

// The inverse of the 3x3 linear part by cofactors; the caller checks that
// the determinant is not zero.
void invert3(const double m[3][4], double out[3][3]) {
  const double det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
                     m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
                     m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) {
      const int r1 = (c + 1) % 3, r2 = (c + 2) % 3, c1 = (r + 1) % 3, c2 = (r + 2) % 3;
      out[r][c] = (m[r1][c1] * m[r2][c2] - m[r1][c2] * m[r2][c1]) / det;
    }
}

}  // namespace

Vec3d Domain::index(const Vec3d& world) const {
  if (to_world.determinant() == 0.0) throw InvalidArgument(what + ": the transform is singular");
  double inv[3][3];
  invert3(to_world.m, inv);
  const Vec3d d{world[0] - to_world.m[0][3], world[1] - to_world.m[1][3], world[2] - to_world.m[2][3]};
  Vec3d out;
  for (int r = 0; r < 3; ++r) out[r] = inv[r][0] * d[0] + inv[r][1] * d[1] + inv[r][2] * d[2];
  return out;
}

Vec3d Domain::world_min() const {
  Vec3d out{HUGE_VAL, HUGE_VAL, HUGE_VAL};
  for (int c = 0; c < 8; ++c) {
    const Vec3d p = world({double((c & 1) ? hi[0] : lo[0]), double((c & 2) ? hi[1] : lo[1]),
                           double((c & 4) ? hi[2] : lo[2])});
    for (int a = 0; a < 3; ++a) out[a] = std::min(out[a], p[a]);
  }
  return out;
}

Vec3d Domain::world_max() const {
  Vec3d out{-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
  for (int c = 0; c < 8; ++c) {
    const Vec3d p = world({double((c & 1) ? hi[0] : lo[0]), double((c & 2) ? hi[1] : lo[1]),
                           double((c & 4) ? hi[2] : lo[2])});
    for (int a = 0; a < 3; ++a) out[a] = std::max(out[a], p[a]);
  }
  return out;
}

void Domain::require_inside(const Vec3d& p, const std::string& label) const {
  for (int a = 0; a < 3; ++a) {
    const double slack = 1e-9 * std::max(1.0, double(hi[a] - lo[a]));
    if (!(p[a] >= lo[a] - slack && p[a] <= hi[a] + slack)) {
      const Vec3d w = world(p);
      throw InvalidArgument(what + ": " + label + " (" + std::to_string(w[0]) + ", " +
                            std::to_string(w[1]) + ", " + std::to_string(w[2]) +
                            ") is outside the domain (index " + std::to_string(lo[0]) + ".." +
                            std::to_string(hi[0]) + ", " + std::to_string(lo[1]) + ".." +
                            std::to_string(hi[1]) + ", " + std::to_string(lo[2]) + ".." +
                            std::to_string(hi[2]) + ")");
    }
  }
}

SampleRegion::SampleRegion(const ScalarGrid& grid, const Index3& lo, const Index3& hi) : lo_(lo) {
  for (int a = 0; a < 3; ++a) dims_[a] = hi[a] - lo[a] + 1;
  grid.bricks->fill_region(lo_, dims_, float(grid.background), values_);
}

double SampleRegion::trilinear(const Vec3d& p) const {
  int i0[3], i1[3];
  double t[3];
  for (int a = 0; a < 3; ++a) {
    const double x = std::clamp(p[a] - double(lo_[a]), 0.0, double(dims_[a] - 1));
    const int cell = std::min(int(std::floor(x)), std::max(dims_[a] - 2, 0));
    i0[a] = lo_[a] + cell;
    i1[a] = lo_[a] + std::min(cell + 1, dims_[a] - 1);
    t[a] = x - double(cell);
  }
  double f = 0.0;
  for (int c = 0; c < 8; ++c) {
    const double w = ((c & 1) ? t[0] : 1 - t[0]) * ((c & 2) ? t[1] : 1 - t[1]) *
                     ((c & 4) ? t[2] : 1 - t[2]);
    if (w == 0.0) continue;
    f += w * at((c & 1) ? i1[0] : i0[0], (c & 2) ? i1[1] : i0[1], (c & 4) ? i1[2] : i0[2]);
  }
  return f;
}

}  // namespace isoform::visualize

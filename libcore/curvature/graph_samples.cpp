// The grid map as the curvature fits use it.
#include "graph_samples.h"

#include <Eigen/LU>
#include <cmath>

#include "../errors.h"

namespace isoform {

GraphAxes GraphAxes::of(const Affine& index_to_world) {
  Eigen::Matrix3d l;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) l(r, c) = index_to_world.m[r][c];
  const double det = l.determinant();
  const double scale = l.cwiseAbs().maxCoeff();
  // Relative to the voxel size cubed: a map this close to singular has a
  // flat voxel and no usable curvature.
  if (!std::isfinite(det) || scale == 0 || std::abs(det) < 1e-12 * scale * scale * scale)
    throw InvalidArgument("the grid's index-to-world transform is singular");
  const Eigen::Matrix3d it = l.inverse().transpose();
  GraphAxes a;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) {
      a.linear[r][c] = l(r, c);
      a.inverse_transpose[r][c] = it(r, c);
    }
  return a;
}

std::array<double, 3> GraphAxes::world_offset(int i, int j, int k) const {
  std::array<double, 3> w;
  for (int r = 0; r < 3; ++r) w[size_t(r)] = linear[r][0] * i + linear[r][1] * j + linear[r][2] * k;
  return w;
}

std::array<double, 3> GraphAxes::world_gradient(const std::array<double, 3>& g) const {
  std::array<double, 3> w;
  for (int r = 0; r < 3; ++r)
    w[size_t(r)] = inverse_transpose[r][0] * g[0] + inverse_transpose[r][1] * g[1] + inverse_transpose[r][2] * g[2];
  return w;
}

}  // namespace isoform

// Principal curvatures from a symmetric 3x3 matrix (Theorem 4.7, 4.36).
#include "graph_principal.h"

#include <Eigen/Eigenvalues>
#include <cmath>

namespace isoform {

GraphPrincipal graph_principal_symmetric(const Sym3& c) {
  Eigen::Matrix3d m;
  for (int i = 0; i < 3; ++i)
    for (int j = i; j < 3; ++j) m(i, j) = m(j, i) = c[size_t(i)][size_t(j)];
  // NOTE: compute() (Householder tridiagonalisation and implicit QR) rather
  // than computeDirect(): the closed-form cubic loses digits when two
  // eigenvalues nearly coincide, as they do on spherical test functions.
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(m, Eigen::EigenvaluesOnly);
  const Eigen::Vector3d e = solver.eigenvalues();  // ascending
  GraphPrincipal p;
  p.k1 = e[2];
  p.k2 = e[1];
  p.k3 = e[0];
  p.mean = (p.k1 + p.k2 + p.k3) / 3.0;
  p.gauss = p.k1 * p.k2 * p.k3;
  return p;
}

GraphPrincipal graph_principal_from_derivatives(const std::array<double, 3>& g, const Sym3& hess) {
  const double g2 = g[0] * g[0] + g[1] * g[1] + g[2] * g[2];
  const double l = std::sqrt(1.0 + g2);
  Eigen::Matrix3d h, p = Eigen::Matrix3d::Identity();
  for (int i = 0; i < 3; ++i)
    for (int j = i; j < 3; ++j) h(i, j) = h(j, i) = hess[size_t(i)][size_t(j)];
  if (g2 > 0) {
    const Eigen::Vector3d gv(g[0], g[1], g[2]);
    p += ((1.0 / l - 1.0) / g2) * (gv * gv.transpose());
  }
  const Eigen::Matrix3d s = (p * h * p) / l;
  Sym3 c;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) c[size_t(i)][size_t(j)] = 0.5 * (s(i, j) + s(j, i));
  return graph_principal_symmetric(c);
}

}  // namespace isoform

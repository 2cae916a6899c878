// Principal curvatures of the graph of a trivariate function (Hamann 1991,
// Section 4.3): k1 >= k2 >= k3, their mean H (4.38) and product K.
#pragma once

#include <array>

namespace isoform {

using Sym3 = std::array<std::array<double, 3>, 3>;

struct GraphPrincipal {
  double k1 = 0, k2 = 0, k3 = 0;  // k1 >= k2 >= k3
  double mean = 0;                 // H = (k1 + k2 + k3) / 3
  double gauss = 0;                // K = k1 k2 k3
};

// Theorem 4.7: the eigenvalues of the symmetric matrix of the osculating
// quadric's coefficients, by Eigen's iterative symmetric eigensolver (not
// Newton's method on the cubic 4.50, which Remark 4.4 uses). Only the upper
// triangle of c is read.
GraphPrincipal graph_principal_symmetric(const Sym3& c);

// Equation 4.36: the eigenvalues of -A = (1/l) Hess (I + g g^T)^{-1} for a
// world gradient g and Hessian hess (upper triangle read). -A is not
// symmetric; with P = (I + g g^T)^{-1/2} = I + (1/l - 1) g g^T / |g|^2 it is
// similar to the symmetric (1/l) P Hess P, whose eigenvalues are taken.
GraphPrincipal graph_principal_from_derivatives(const std::array<double, 3>& g, const Sym3& hess);

}  // namespace isoform

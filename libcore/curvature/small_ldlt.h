// An LDL^T factorisation of a small symmetric matrix of fixed size, in plain
// arrays, without pivoting.
//
// NOTE: the fits give it Gram matrices (normal equations), which are
// positive semidefinite; for a positive definite matrix the factorisation
// is stable without pivoting (it is Cholesky's, with the square roots left
// out), and a matrix that is singular or nearly so shows it in a pivot that
// is zero, negative or small beside the largest, which the callers'
// conditioning test (smallest over largest pivot) refuses. The
// factorisation is right-looking, whose inner loops are independent updates
// of a row instead of the dot products (chains of dependent adds) of the
// left-looking form. The matrix is read through an index table (entry
// (r, c) is values[at[r][c]]), so a Gram matrix of moments is read straight
// from its moments, with no branch on r >= c.
#pragma once

#include <cmath>
#include <limits>

namespace isoform {

template <int N>
class SmallLdlt {
 public:
  // Factors the symmetric matrix whose entry (r, c) is values[at[r][c]]
  // (at symmetric). False at the first pivot that is zero or not finite (D
  // is then incomplete).
  bool factor(const double* values, const int (&at)[N][N]) {
    for (int i = 0; i < N; ++i)
      for (int j = 0; j <= i; ++j) m_[i][j] = values[at[i][j]];
    for (int k = 0; k < N; ++k) {
      const double dk = m_[k][k];
      if (!(std::abs(dk) > 0.0) || !std::isfinite(dk)) {
        for (int i = k + 1; i < N; ++i) m_[i][i] = 0.0;
        return false;
      }
      // Column k before scaling is D_k L_jk; the trailing update subtracts
      // L_ik D_k L_jk from entry (i, j).
      const double inv = 1.0 / dk;
      double w[N];
      for (int i = k + 1; i < N; ++i) w[i] = m_[i][k];
      for (int i = k + 1; i < N; ++i) {
        const double l = w[i] * inv;
        m_[i][k] = l;
        double* row = m_[i];
        for (int j = k + 1; j <= i; ++j) row[j] -= l * w[j];
      }
    }
    return true;
  }

  // The i-th entry of D.
  double d(int i) const { return m_[i][i]; }

  // Solves A x = b after a successful factor(); entries of D at or below the
  // smallest normal double count as zero (their component of x is 0).
  void solve(const double (&b)[N], double (&x)[N]) const {
    double y[N];
    for (int i = 0; i < N; ++i) y[i] = b[i];
    for (int j = 0; j < N; ++j)
      for (int i = j + 1; i < N; ++i) y[i] -= m_[i][j] * y[j];
    for (int i = 0; i < N; ++i) y[i] = std::abs(m_[i][i]) > std::numeric_limits<double>::min() ? y[i] / m_[i][i] : 0.0;
    for (int j = N - 1; j >= 0; --j)
      for (int i = 0; i < j; ++i) y[i] -= m_[j][i] * y[j];
    for (int i = 0; i < N; ++i) x[i] = y[i];
  }

 private:
  double m_[N][N];
};

}  // namespace isoform

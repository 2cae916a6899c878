// A pivoted LDL^T factorisation of a small symmetric matrix of fixed size,
// in plain arrays, with the pivots of Eigen's LDLT: so its D, and the
// decisions taken on D, match Eigen's up to rounding.
//
// NOTE: Eigen's LDLT is left-looking: step k pivots on the largest diagonal
// entry among k..N-1, and those entries are still the matrix's own (each is
// updated only at its own step). The pivot order therefore depends on the
// diagonal alone. Here it is found first, the matrix gathered once in that
// order, and the factorisation done right-looking, whose inner loops are
// independent updates of a row instead of the dot products (chains of
// dependent adds) of the left-looking form. The matrix is read through an
// index table (entry (r, c) is values[at[r][c]]), so a Gram matrix of
// moments is permuted straight from its moments, with no branch on r >= c.
#pragma once

#include <cmath>
#include <limits>
#include <utility>

namespace isoform {

template <int N>
class SmallLdlt {
 public:
  // Factors the symmetric matrix whose entry (r, c) is values[at[r][c]]
  // (at symmetric). False at the first pivot that is zero or not finite (D
  // is then incomplete).
  bool factor(const double* values, const int (&at)[N][N]) {
    // Eigen's transpositions, applied to the diagonal: step k swaps k with
    // the first largest |diagonal| among k..N-1.
    double diag[N];
    for (int i = 0; i < N; ++i) {
      diag[i] = std::abs(values[at[i][i]]);
      order_[i] = i;
    }
    for (int k = 0; k < N - 1; ++k) {
      int p = k;
      double best = diag[k];
      for (int i = k + 1; i < N; ++i) {
        const bool larger = diag[i] > best;
        best = larger ? diag[i] : best;
        p = larger ? i : p;
      }
      std::swap(diag[k], diag[p]);
      std::swap(order_[k], order_[p]);
    }
    // m = P A P^T, lower triangle.
    for (int i = 0; i < N; ++i) {
      const int* row = at[order_[i]];
      for (int j = 0; j <= i; ++j) m_[i][j] = values[row[order_[j]]];
    }
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

  // The i-th entry of D (of the permuted matrix).
  double d(int i) const { return m_[i][i]; }

  // Solves A x = b after a successful factor(); entries of D at or below the
  // smallest normal double count as zero (their component of x is 0), as in
  // Eigen.
  void solve(const double (&b)[N], double (&x)[N]) const {
    double y[N];
    for (int i = 0; i < N; ++i) y[i] = b[order_[i]];
    for (int j = 0; j < N; ++j)
      for (int i = j + 1; i < N; ++i) y[i] -= m_[i][j] * y[j];
    for (int i = 0; i < N; ++i) y[i] = std::abs(m_[i][i]) > std::numeric_limits<double>::min() ? y[i] / m_[i][i] : 0.0;
    for (int j = N - 1; j >= 0; --j)
      for (int i = 0; i < j; ++i) y[i] -= m_[j][i] * y[j];
    for (int i = 0; i < N; ++i) x[order_[i]] = y[i];
  }

 private:
  double m_[N][N];
  int order_[N];  // row i of the permuted matrix is row order_[i] of the input
};

}  // namespace isoform

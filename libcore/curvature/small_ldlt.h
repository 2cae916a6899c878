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
#include <cstring>
#include <limits>
#include <utility>

namespace isoform {

// Eigen's pivot order for a diagonal of magnitudes diag: step k of its
// LDLT swaps k with the first largest entry among k..N-1, so row order[k]
// of the input becomes row k.
//
// NOTE: with distinct entries that is the entries by decreasing size, so
// each entry's place is the number of entries larger than it: counted here
// for all entries at once in vectors, with no chain of dependent swaps.
// Where two places coincide (equal entries, or a NaN, which nothing is
// larger than) the steps are taken one by one as Eigen takes them.
template <int N>
inline __attribute__((always_inline)) void pivot_order(const double (&diag)[N], int (&order)[N]) {
  typedef double Quad __attribute__((vector_size(32)));
  typedef long long Count __attribute__((vector_size(32)));
  constexpr int kBlocks = (N + 3) / 4;
  double padded[4 * kBlocks];
  for (int i = 0; i < 4 * kBlocks; ++i) padded[i] = i < N ? diag[i] : -1.0;  // -1: larger than no entry
  Quad all[kBlocks];
  std::memcpy(all, padded, sizeof(all));
  // A comparison is -1 where true: place = -(sum of "j larger than i").
  Count place[kBlocks] = {};
  for (int j = 0; j < N; ++j) {
    const double dj = diag[j];
    for (int b = 0; b < kBlocks; ++b) place[b] += (Quad{dj, dj, dj, dj} > all[b]);
  }
  unsigned taken = 0;
  for (int i = 0; i < N; ++i) {
    const int at = int(-place[i / 4][i % 4]);
    taken |= 1u << at;
    order[at] = i;
  }
  if (taken == (1u << N) - 1) return;
  double rest[N];
  for (int i = 0; i < N; ++i) {
    rest[i] = diag[i];
    order[i] = i;
  }
  for (int k = 0; k < N - 1; ++k) {
    int p = k;
    double best = rest[k];
    for (int i = k + 1; i < N; ++i) {
      const bool larger = rest[i] > best;
      best = larger ? rest[i] : best;
      p = larger ? i : p;
    }
    std::swap(rest[k], rest[p]);
    std::swap(order[k], order[p]);
  }
}

template <int N>
class SmallLdlt {
 public:
  // Factors the symmetric matrix whose entry (r, c) is values[at[r][c]]
  // (at symmetric). False at the first pivot that is zero or not finite (D
  // is then incomplete).
  bool factor(const double* values, const int (&at)[N][N]) {
    double diag[N];
    for (int i = 0; i < N; ++i) diag[i] = std::abs(values[at[i][i]]);
    pivot_order<N>(diag, order_);
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

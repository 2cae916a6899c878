// SmallLdlt (small_ldlt.h) for four matrices at once, one in each lane of a
// vector (entry k of lane l is values[k][l]): each lane pivots by its own
// diagonal, and the factorisation then
// runs the same operations on every lane, so each lane's D and solution have
// the bits SmallLdlt gives for that matrix alone (no fused multiply-add in
// either, lane-wise IEEE arithmetic).
#pragma once

#include <cmath>
#include <limits>
#include <utility>

#include "small_ldlt.h"

namespace isoform {

typedef double Lanes4 __attribute__((vector_size(32)));

template <int N>
class SmallLdltLanes {
 public:
  // Lane l factors the matrix whose entry (r, c) is values[at[r][c]][l].
  // ok[l] is false where SmallLdlt::factor would return false; that lane's
  // D is then not SmallLdlt's and must not be used.
  __attribute__((always_inline)) void factor(const Lanes4* values, const int (&at)[N][N], bool (&ok)[4]) {
    for (int l = 0; l < 4; ++l) {
      double diag[N];
      for (int i = 0; i < N; ++i) diag[i] = std::abs(values[at[i][i]][l]);
      pivot_order<N>(diag, order_[l]);
      ok[l] = true;
    }
    const int *o0 = order_[0], *o1 = order_[1], *o2 = order_[2], *o3 = order_[3];
    bool shared = true;
    for (int i = 0; i < N; ++i) shared &= (o0[i] == o1[i]) & (o0[i] == o2[i]) & (o0[i] == o3[i]);
    if (shared) {
      // One order for all four lanes: whole vectors, as they are.
      for (int i = 0; i < N; ++i) {
        const int* row = at[o0[i]];
        for (int j = 0; j <= i; ++j) m_[i][j] = values[row[o0[j]]];
      }
    } else {
      // Whole vectors built from four loads (no lane-wise stores into m_,
      // which would stall the vector loads that follow).
      for (int i = 0; i < N; ++i) {
        const int *r0 = at[o0[i]], *r1 = at[o1[i]], *r2 = at[o2[i]], *r3 = at[o3[i]];
        for (int j = 0; j <= i; ++j)
          m_[i][j] = Lanes4{values[r0[o0[j]]][0], values[r1[o1[j]]][1], values[r2[o2[j]]][2], values[r3[o3[j]]][3]};
      }
    }
    // Unrolled whole (N is at most 14: 455 updates), so every index is a
    // constant and m_ stays where the compiler can keep it.
#pragma GCC unroll 16
    for (int k = 0; k < N; ++k) {
      const Lanes4 dk = m_[k][k];
      for (int l = 0; l < 4; ++l) {
        const double x = dk[l];
        if (!(std::abs(x) > 0.0) || !std::isfinite(x)) ok[l] = false;
      }
      const Lanes4 inv = 1.0 / dk;
      Lanes4 w[N];
#pragma GCC unroll 16
      for (int i = k + 1; i < N; ++i) w[i] = m_[i][k];
#pragma GCC unroll 16
      for (int i = k + 1; i < N; ++i) {
        const Lanes4 f = w[i] * inv;
        m_[i][k] = f;
        Lanes4* row = m_[i];
#pragma GCC unroll 16
        for (int j = k + 1; j <= i; ++j) row[j] -= f * w[j];
      }
    }
  }

  double d(int lane, int i) const { return m_[i][i][lane]; }

  // SmallLdlt::solve for every lane: x[l] from lane l of b.
  __attribute__((always_inline)) void solve(const Lanes4* b, double* const (&x)[4]) const {
    Lanes4 y[N];
    for (int i = 0; i < N; ++i) y[i] = Lanes4{b[order_[0][i]][0], b[order_[1][i]][1], b[order_[2][i]][2], b[order_[3][i]][3]};
#pragma GCC unroll 16
    for (int j = 0; j < N; ++j)
#pragma GCC unroll 16
      for (int i = j + 1; i < N; ++i) y[i] -= m_[i][j] * y[j];
    const Lanes4 tiny = {std::numeric_limits<double>::min(), std::numeric_limits<double>::min(),
                         std::numeric_limits<double>::min(), std::numeric_limits<double>::min()};
    const Lanes4 zero = {0.0, 0.0, 0.0, 0.0};
    for (int i = 0; i < N; ++i) {
      const Lanes4 dd = m_[i][i];
      const Lanes4 mag = dd < zero ? -dd : dd;
      y[i] = mag > tiny ? y[i] / dd : zero;
    }
#pragma GCC unroll 16
    for (int j = N - 1; j >= 0; --j)
#pragma GCC unroll 16
      for (int i = 0; i < j; ++i) y[i] -= m_[j][i] * y[j];
    for (int i = 0; i < N; ++i) {
      const Lanes4 yi = y[i];
      x[0][order_[0][i]] = yi[0];
      x[1][order_[1][i]] = yi[1];
      x[2][order_[2][i]] = yi[2];
      x[3][order_[3][i]] = yi[3];
    }
  }

 private:
  Lanes4 m_[N][N];
  int order_[4][N];
};

}  // namespace isoform

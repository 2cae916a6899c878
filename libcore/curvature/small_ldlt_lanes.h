// SmallLdlt (small_ldlt.h) for four matrices at once, one in each lane of a
// vector (entry k of lane l is values[k][l]): the same operations on every
// lane, so each lane's D and solution have the bits SmallLdlt gives for that
// matrix alone (no fused multiply-add in either, lane-wise IEEE arithmetic).
#pragma once

#include <cmath>
#include <limits>

#include "lanes4.h"

namespace isoform {

template <int N>
class SmallLdltLanes {
 public:
  // Lane l factors the matrix whose entry (r, c) is values[at[r][c]][l].
  // ok[l] is false where SmallLdlt::factor would return false; that lane's
  // D is then not SmallLdlt's and must not be used.
  __attribute__((always_inline)) void factor(const Lanes4* values, const int (&at)[N][N], bool (&ok)[4]) {
    for (int l = 0; l < 4; ++l) ok[l] = true;
    for (int i = 0; i < N; ++i)
      for (int j = 0; j <= i; ++j) m_[i][j] = values[at[i][j]];
    // Unrolled whole (N is at most 14: 455 updates), so every index is a
    // constant.
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

  // The i-th entry of D in every lane.
  Lanes4 diagonal(int i) const { return m_[i][i]; }

  // SmallLdlt::solve for every lane: lane l of x from lane l of b.
  __attribute__((always_inline)) void solve(const Lanes4* b, Lanes4* x) const {
    Lanes4 y[N];
    for (int i = 0; i < N; ++i) y[i] = b[i];
#pragma GCC unroll 16
    for (int j = 0; j < N; ++j)
#pragma GCC unroll 16
      for (int i = j + 1; i < N; ++i) y[i] -= m_[i][j] * y[j];
    const Lanes4 tiny = splat4(std::numeric_limits<double>::min()), zero = splat4(0.0);
    for (int i = 0; i < N; ++i) {
      const Lanes4 dd = m_[i][i];
      const Lanes4 mag = dd < zero ? -dd : dd;
      y[i] = mag > tiny ? y[i] / dd : zero;
    }
#pragma GCC unroll 16
    for (int j = N - 1; j >= 0; --j)
#pragma GCC unroll 16
      for (int i = 0; i < j; ++i) y[i] -= m_[j][i] * y[j];
    for (int i = 0; i < N; ++i) x[i] = y[i];
  }

  // The same, lane l's solution into x[l][0 .. N - 1].
  __attribute__((always_inline)) void solve(const Lanes4* b, double* const (&x)[4]) const {
    Lanes4 y[N];
    solve(b, y);
    for (int i = 0; i < N; ++i) {
      const Lanes4 yi = y[i];
      x[0][i] = yi[0];
      x[1][i] = yi[1];
      x[2][i] = yi[2];
      x[3][i] = yi[3];
    }
  }

 private:
  Lanes4 m_[N][N];
};

}  // namespace isoform

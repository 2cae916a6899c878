// SmallLdlt (small_ldlt.h) for four matrices at once (V = Lanes4), or eight
// (V = Lanes8), one in each lane of a vector (entry k of lane l is
// values[k][l]): the same operations on every lane, so each lane's D and
// solution have the bits SmallLdlt gives for that matrix alone (no fused
// multiply-add in either, lane-wise IEEE arithmetic).
#pragma once

#include <cmath>
#include <limits>
#include <type_traits>

#include "lanes4.h"

namespace isoform {

template <int N, class V = Lanes4>
class SmallLdltLanes {
  using Mask = decltype(V{} < V{});  // a comparison's result: all ones or zero per lane

 public:
  static constexpr int kLanes = int(sizeof(V) / sizeof(double));

  // Lane l factors the matrix whose entry (r, c) is values[at[r][c]][l].
  // ok[l] is false where SmallLdlt::factor would return false; that lane's
  // D is then not SmallLdlt's and must not be used.
  //
  // Left-looking, entry by entry, row after row: entry (i, j) takes its
  // updates L_ik (D_k L_jk) in the order k = 0, 1, ..., as the right-looking
  // SmallLdlt applies them, so the same bits; but each entry's updates run
  // in a register and the entry is stored once, where the right-looking
  // form loads and stores every entry of the trailing block at every step
  // (four matrices at once do not leave registers for the block). The
  // dependent chains are short (at most N - 1 updates) and many, unrolled
  // whole, so they overlap.
  __attribute__((always_inline)) void factor(const V* values, const int (&at)[N][N], bool (&ok)[kLanes]) {
    V w[N][N];  // below the diagonal: D_j L_ij, before scaling
    V inv[N];   // 1 / D_j
    // A pivot's magnitude is usable (finite, above zero) when its bits b
    // lie in [1, 0x7FEFFFFFFFFFFFFF]: then neither b - 1 nor b + 2^52 has
    // the top bit set. The top bits are collected by integer arithmetic
    // alone (comparisons of eight lanes GCC turns into a mask built one
    // lane at a time).
    using Bits = std::conditional_t<sizeof(V) == sizeof(Bits4), Bits4, Bits8>;
    Bits bad = {};
    const Mask magnitude = Mask{} + INT64_MAX;  // std::abs: the sign bit cleared
#pragma GCC unroll 16
    for (int i = 0; i < N; ++i) {
#pragma GCC unroll 16
      for (int j = 0; j <= i; ++j) {
        V acc = values[at[i][j]];
#pragma GCC unroll 16
        for (int k = 0; k < j; ++k) acc -= m_[i][k] * w[j][k];
        if (j < i) {
          w[i][j] = acc;
          m_[i][j] = acc * inv[j];
        } else {
          // A pivot that is zero or not finite: SmallLdlt::factor stops.
          const V mag = (V)((Mask)acc & magnitude);
          const Bits b = (Bits)mag;
          bad |= (b - 1) | (b + (uint64_t(1) << 52));
          m_[i][i] = acc;
          inv[i] = 1.0 / acc;
        }
      }
    }
    for (int l = 0; l < kLanes; ++l) ok[l] = (bad[l] >> 63) == 0;
  }

  double d(int lane, int i) const { return m_[i][i][lane]; }

  // The i-th entry of D in every lane.
  V diagonal(int i) const { return m_[i][i]; }

  // SmallLdlt::solve for every lane: lane l of x from lane l of b. Entry
  // by entry, as in factor(): each entry's updates in SmallLdlt's order.
  __attribute__((always_inline)) void solve(const V* b, V* x) const {
    V z[N], y[N];  // L z = b, D y = z
    const V tiny = V{} + std::numeric_limits<double>::min(), zero = V{};
#pragma GCC unroll 16
    for (int i = 0; i < N; ++i) {
      V acc = b[i];
#pragma GCC unroll 16
      for (int j = 0; j < i; ++j) acc -= m_[i][j] * z[j];
      z[i] = acc;
      const V dd = m_[i][i];
      const V mag = dd < zero ? -dd : dd;
      y[i] = mag > tiny ? acc / dd : zero;
    }
#pragma GCC unroll 16
    for (int i = N - 1; i >= 0; --i) {
      V acc = y[i];
#pragma GCC unroll 16
      for (int j = N - 1; j > i; --j) acc -= m_[j][i] * x[j];
      x[i] = acc;
    }
  }

  // The same, lane l's solution into x[l][0 .. N - 1].
  __attribute__((always_inline)) void solve(const V* b, double* const (&x)[kLanes]) const {
    V y[N];
    solve(b, y);
    for (int i = 0; i < N; ++i) {
      const V yi = y[i];
      for (int l = 0; l < kLanes; ++l) x[l][i] = yi[l];
    }
  }

 private:
  V m_[N][N];
};

}  // namespace isoform

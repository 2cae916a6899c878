// Least-squares height fits, one fixed-size instance per model (no heap, no
// per-vertex dynamic sizes, no Eigen: at 3 to 14 unknowns its dynamic blocks
// cost more than the arithmetic).
//
// NOTE: the normal equations are formed from moments. Entry (r, c) of A^T A
// is the sum over the points of u^(i_r + i_c) v^(j_r + j_c), so the quartic's
// 14 x 14 matrix needs only the 42 moments of degree 2 to 8, and A^T d the 14
// sums of d u^i v^j: 56 products per point instead of the 119 of A^T A and
// A^T d. The sums are the same ones in another rounding order.
#include "height_fit.h"

#include <algorithm>
#include <cmath>

#include "small_ldlt.h"

namespace isoform {
namespace {

// Two points at a time, one in each lane; the lanes are added at the end.
typedef double Pair __attribute__((vector_size(16)));

// A model's monomials u^i v^j: degrees lo to hi, within a degree by
// increasing power of v (first the linear terms when lo is 1, then u^2, u v,
// v^2, then higher degrees). The moments are listed the same way, degrees
// 2 lo to 2 hi.
template <int Lo, int Hi>
struct Model {
  static constexpr int kTerms = (Hi + 1) * (Hi + 2) / 2 - Lo * (Lo + 1) / 2;
  static constexpr int kTop = 2 * Hi;  // the highest moment degree
  static constexpr int kMoments = (kTop + 1) * (kTop + 2) / 2 - (2 * Lo) * (2 * Lo + 1) / 2;
  // Index of u^a v^b among the moments.
  static constexpr int moment(int a, int b) {
    const int s = a + b;
    return s * (s + 1) / 2 - (2 * Lo) * (2 * Lo + 1) / 2 + b;
  }
};

// moment[k] = sum of u^a v^b, rhs[k] = sum of d u^i v^j over the scaled
// points, fully unrolled over the model's terms.
template <int Lo, int Hi>
void accumulate(const double* u, const double* v, const double* d, int count, double inv,
                double (&moment)[Model<Lo, Hi>::kMoments], double (&rhs)[Model<Lo, Hi>::kTerms]) {
  constexpr int kTop = Model<Lo, Hi>::kTop, kMoments = Model<Lo, Hi>::kMoments, kTerms = Model<Lo, Hi>::kTerms;
  Pair m[kMoments] = {}, r[kTerms] = {};
  for (int j = 0; j < count; j += 2) {
    // An odd count pads the second lane with the origin, which adds 0 to
    // every sum (no moment or term has degree 0).
    const bool two = j + 1 < count;
    const Pair x = {u[j] * inv, two ? u[j + 1] * inv : 0.0}, y = {v[j] * inv, two ? v[j + 1] * inv : 0.0};
    const Pair h = {d[j], two ? d[j + 1] : 0.0};
    Pair pu[kTop + 1], pv[kTop + 1];
    pu[0] = pv[0] = Pair{1.0, 1.0};
    pu[1] = x;
    pv[1] = y;
#pragma GCC unroll 16
    for (int a = 2; a <= kTop; ++a) {
      pu[a] = pu[a - 1] * x;
      pv[a] = pv[a - 1] * y;
    }
    int k = 0;
#pragma GCC unroll 16
    for (int s = 2 * Lo; s <= kTop; ++s)
#pragma GCC unroll 16
      for (int b = 0; b <= s; ++b, ++k) m[k] += pu[s - b] * pv[b];
    k = 0;
#pragma GCC unroll 16
    for (int s = Lo; s <= Hi; ++s)
#pragma GCC unroll 16
      for (int b = 0; b <= s; ++b, ++k) r[k] += h * (pu[s - b] * pv[b]);
  }
  for (int k = 0; k < kMoments; ++k) moment[k] = m[k][0] + m[k][1];
  for (int k = 0; k < kTerms; ++k) rhs[k] = r[k][0] + r[k][1];
}

template <int Lo, int Hi>
HeightFit fit(const double* u, const double* v, const double* d, int count, double min_rcond) {
  using M = Model<Lo, Hi>;
  constexpr int kTerms = M::kTerms;
  HeightFit out;
  if (count < kTerms) return out;
  // Coordinates scaled by the largest |(u, v)|, so the conditioning check
  // does not depend on the mesh's size.
  double r2 = 0.0;
  for (int j = 0; j < count; ++j) r2 = std::max(r2, u[j] * u[j] + v[j] * v[j]);
  const double scale = std::sqrt(r2);
  if (!(scale > 0.0) || !std::isfinite(scale)) return out;
  double moment[M::kMoments], rhs[kTerms];
  accumulate<Lo, Hi>(u, v, d, count, 1.0 / scale, moment, rhs);
  // The exponents of each term, in the model's order.
  int eu[kTerms], ev[kTerms], n = 0;
  for (int deg = Lo; deg <= Hi; ++deg)
    for (int k = 0; k <= deg; ++k, ++n) {
      eu[n] = deg - k;
      ev[n] = k;
    }
  double ata[kTerms][kTerms];
  for (int r = 0; r < kTerms; ++r)
    for (int c = 0; c <= r; ++c) ata[r][c] = moment[M::moment(eu[r] + eu[c], ev[r] + ev[c])];
  SmallLdlt<kTerms> ldlt;
  const bool factored = ldlt.factor(ata);
  double hi = 0.0, lo = ldlt.d(0);
  for (int i = 0; i < kTerms; ++i) {
    hi = std::max(hi, std::abs(ldlt.d(i)));
    lo = std::min(lo, ldlt.d(i));
  }
  out.rcond = hi > 0.0 ? lo / hi : 0.0;
  // A zero or negative pivot gives rcond <= 0, below any useful min_rcond.
  if (!factored || !(lo > 0.0) || !(out.rcond >= min_rcond)) return out;
  double c[kTerms];
  ldlt.solve(rhs, c);
  for (double x : c)
    if (!std::isfinite(x)) return out;
  // Back from the scaled coordinates: a coefficient of u^i v^j carries
  // scale^-(i+j). Linear terms come first (u, v), then u^2, u v, v^2.
  const int q = Lo == 1 ? 2 : 0;
  if (q) {
    out.fu = c[0] / scale;
    out.fv = c[1] / scale;
  }
  const double s2 = scale * scale;
  out.fuu = 2.0 * c[q] / s2;
  out.fuv = c[q + 1] / s2;
  out.fvv = 2.0 * c[q + 2] / s2;
  out.ok = true;
  return out;
}

}  // namespace

int fit_terms(FitModel model) {
  switch (model) {
    case FitModel::SeedQuadratic: return Model<2, 2>::kTerms;
    case FitModel::Quadric: return Model<1, 2>::kTerms;
    case FitModel::Cubic: return Model<1, 3>::kTerms;
    case FitModel::Quartic: return Model<1, 4>::kTerms;
  }
  return Model<2, 2>::kTerms;
}

HeightFit fit_height(FitModel model, const double* u, const double* v, const double* d, int count,
                     double min_rcond) {
  switch (model) {
    case FitModel::SeedQuadratic: return fit<2, 2>(u, v, d, count, min_rcond);
    case FitModel::Quadric: return fit<1, 2>(u, v, d, count, min_rcond);
    case FitModel::Cubic: return fit<1, 3>(u, v, d, count, min_rcond);
    case FitModel::Quartic: return fit<1, 4>(u, v, d, count, min_rcond);
  }
  return HeightFit{};
}

}  // namespace isoform

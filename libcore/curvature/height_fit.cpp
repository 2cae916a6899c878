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
#include <type_traits>
#include <vector>

#include "small_ldlt.h"
#include "small_ldlt_lanes.h"
#include "vector_level.h"

namespace isoform {
namespace {

// The sums run over a point set's points in their order (j = 0, 1, ...),
// one sum per moment: the order both the one-set fit and the side-by-side
// fit keep, so each lane of the latter gives the former's bits. The
// side-by-side fit holds one point set per lane of a vector (no sums across
// lanes at the end, and the moments go to the factorisation as they are);
// its shorter sets are padded with the origin, which adds 0 to every sum (no
// moment or term has degree 0). Without AVX the compiler splits each vector
// operation into two SSE2 ones, lane by lane, so every build gives the same
// bits (no fused multiply-add in any: the curvature sources are built with
// -ffp-contract=off, libcore/CMakeLists.txt).
typedef double Quad __attribute__((vector_size(32)));

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

// Entry (r, c) of the normal equations is moment at[r][c].
// A constant table, so that the unrolled factorisations address the
// moments directly.
template <int Lo, int Hi>
struct GramIndex {
  int at[Model<Lo, Hi>::kTerms][Model<Lo, Hi>::kTerms] = {};
  constexpr GramIndex() {
    int eu[Model<Lo, Hi>::kTerms] = {}, ev[Model<Lo, Hi>::kTerms] = {}, n = 0;
    for (int deg = Lo; deg <= Hi; ++deg)
      for (int k = 0; k <= deg; ++k, ++n) {
        eu[n] = deg - k;
        ev[n] = k;
      }
    for (int r = 0; r < n; ++r)
      for (int c = 0; c < n; ++c) at[r][c] = Model<Lo, Hi>::moment(eu[r] + eu[c], ev[r] + ev[c]);
  }
};

// Adds one point (x, y scaled, height h) to moment[k] (the sums of u^a v^b)
// and rhs[k] (the sums of d u^i v^j), fully unrolled over the model's terms;
// T is double for one point set, Quad for four side by side.
template <int Lo, int Hi, class T>
inline __attribute__((always_inline)) void add_point(T x, T y, T h, T (&moment)[Model<Lo, Hi>::kMoments],
                                                     T (&rhs)[Model<Lo, Hi>::kTerms]) {
  constexpr int kTop = Model<Lo, Hi>::kTop;
  T pu[kTop + 1], pv[kTop + 1];
  pu[0] = pv[0] = T{} + 1.0;
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
    for (int b = 0; b <= s; ++b, ++k) moment[k] += pu[s - b] * pv[b];
  k = 0;
#pragma GCC unroll 16
  for (int s = Lo; s <= Hi; ++s)
#pragma GCC unroll 16
    for (int b = 0; b <= s; ++b, ++k) rhs[k] += h * (pu[s - b] * pv[b]);
}

// The scale of one point set (its largest |(u, v)|, so that the
// conditioning check does not depend on the mesh's size); false with fewer
// points than terms or no usable scale.
template <int Lo, int Hi>
inline __attribute__((always_inline)) bool scale_of(const double* u, const double* v, int count, double& scale) {
  if (count < Model<Lo, Hi>::kTerms) return false;
  double r2 = 0.0;
  for (int j = 0; j < count; ++j) r2 = std::max(r2, u[j] * u[j] + v[j] * v[j]);
  scale = std::sqrt(r2);
  return scale > 0.0 && std::isfinite(scale);
}

// The scale and the sums of one point set; false where scale_of is.
template <int Lo, int Hi>
inline __attribute__((always_inline)) bool prepare(const double* u, const double* v, const double* d, int count,
                                                   double& scale, double (&moment)[Model<Lo, Hi>::kMoments],
                                                   double (&rhs)[Model<Lo, Hi>::kTerms]) {
  if (!scale_of<Lo, Hi>(u, v, count, scale)) return false;
  const double inv = 1.0 / scale;
  for (double& m : moment) m = 0.0;
  for (double& r : rhs) r = 0.0;
  for (int j = 0; j < count; ++j) add_point<Lo, Hi>(u[j] * inv, v[j] * inv, d[j], moment, rhs);
  return true;
}

// rcond from D; false where the fit is not to be trusted.
template <int N, class D>
inline __attribute__((always_inline)) bool conditioned(D d, double min_rcond, HeightFit& out) {
  double hi = 0.0, lo = d(0);
  for (int i = 0; i < N; ++i) {
    hi = std::max(hi, std::abs(d(i)));
    lo = std::min(lo, d(i));
  }
  out.rcond = hi > 0.0 ? lo / hi : 0.0;
  // A zero or negative pivot gives rcond <= 0, below any useful min_rcond.
  return lo > 0.0 && out.rcond >= min_rcond;
}

// The derivatives from the solution c of the scaled normal equations (its
// linear and quadratic coefficients, the first five or three), whose
// entries are all finite.
template <int Lo, int Hi>
inline __attribute__((always_inline)) void derivatives(const double* c, double scale, HeightFit& out) {
  // Back from the scaled coordinates: a coefficient of u^i v^j carries
  // scale^-(i+j). Linear terms come first (u, v), then u^2, u v, v^2.
  const int q = Lo == 1 ? 2 : 0;
  const double inv = 1.0 / scale, inv2 = inv * inv;  // the sums' 1 / scale, squared
  if (q) {
    out.fu = c[0] * inv;
    out.fv = c[1] * inv;
  }
  out.fuu = 2.0 * c[q] * inv2;
  out.fuv = c[q + 1] * inv2;
  out.fvv = 2.0 * c[q + 2] * inv2;
  out.ok = true;
}

// derivatives() where every entry of c is finite.
template <int Lo, int Hi>
inline __attribute__((always_inline)) void finish(const double (&c)[Model<Lo, Hi>::kTerms], double scale,
                                                  HeightFit& out) {
  for (double x : c)
    if (!std::isfinite(x)) return;
  derivatives<Lo, Hi>(c, scale, out);
}

template <int Lo, int Hi>
inline __attribute__((always_inline)) HeightFit fit_body(const double* u, const double* v, const double* d,
                                                         int count, double min_rcond) {
  using M = Model<Lo, Hi>;
  constexpr int kTerms = M::kTerms;
  HeightFit out;
  double scale, moment[M::kMoments], rhs[kTerms];
  if (!prepare<Lo, Hi>(u, v, d, count, scale, moment, rhs)) return out;
  static constexpr GramIndex<Lo, Hi> index{};
  SmallLdlt<kTerms> ldlt;
  const bool factored = ldlt.factor(moment, index.at);
  if (!conditioned<kTerms>([&](int i) { return ldlt.d(i); }, min_rcond, out) || !factored) return out;
  double c[kTerms];
  ldlt.solve(rhs, c);
  finish<Lo, Hi>(c, scale, out);
  return out;
}

// One lane of fit_height_lanes' layout fitted alone (the rare lane the
// side-by-side factorisation cannot take).
template <int Lo, int Hi>
HeightFit fit_lane_alone(const LaneGroup& g, int lane, double min_rcond) {
  const int count = g.count[lane];
  std::vector<double> a(3 * size_t(count));
  for (int j = 0; j < count; ++j) {
    a[size_t(j)] = g.u[4 * size_t(j) + size_t(lane)];
    a[size_t(count + j)] = g.v[4 * size_t(j) + size_t(lane)];
    a[size_t(2 * count + j)] = g.d[4 * size_t(j) + size_t(lane)];
  }
  return fit_body<Lo, Hi>(a.data(), a.data() + count, a.data() + 2 * count, count, min_rcond);
}

// fit_body for G groups of four point sets side by side (fit_height_lanes'
// layout), all 4 G sets in the lanes of one vector: lanes 4 g to 4 g + 3
// are group g's. A lane whose matrix the side-by-side factorisation cannot
// take (a zero or non-finite pivot) is fitted again alone, so every lane's
// result is fit_body's, bit for bit.
template <int Lo, int Hi, int G>
inline __attribute__((always_inline)) void fit_lanes_body(const LaneGroup* group, double min_rcond,
                                                          HeightFit (*out)[4]) {
  using M = Model<Lo, Hi>;
  using V = std::conditional_t<G == 1, Quad, Lanes8>;
  constexpr int kTerms = M::kTerms, kLanes = 4 * G;
  int most = 0;
  for (int g = 0; g < G; ++g)
    for (int c : group[g].count) most = std::max(most, c);
  auto quad = [](const double* a, int j) {
    Quad q;
    __builtin_memcpy(&q, a + 4 * size_t(j), sizeof(q));
    return q;
  };
  // Point j of every group: the groups' quads joined in registers (through
  // memory, a wide load of two narrow stores would wait for both).
  auto at = [&](const double* LaneGroup::*array, int j) {
    if constexpr (G == 1)
      return quad(group[0].*array, j);
    else
      return __builtin_shufflevector(quad(group[0].*array, j), quad(group[1].*array, j), 0, 1, 2, 3, 4, 5, 6, 7);
  };
  // scale_of in every lane: the largest |(u, v)| (the zeros of the padding
  // leave it as it is), as std::max takes it.
  V r2 = {};
  for (int j = 0; j < most; ++j) {
    const V x = at(&LaneGroup::u, j), y = at(&LaneGroup::v, j), q = x * x + y * y;
    r2 = r2 < q ? q : r2;
  }
  double scale[kLanes];
  bool live[kLanes], any = false;
  V inv = {};
  for (int l = 0; l < kLanes; ++l) {
    out[l / 4][l % 4] = HeightFit{};
    scale[l] = std::sqrt(r2[l]);
    live[l] = group[l / 4].count[l % 4] >= kTerms && scale[l] > 0.0 && std::isfinite(scale[l]);
    if (live[l]) inv[l] = 1.0 / scale[l];
    any = any || live[l];
  }
  if (!any) return;
  V m[M::kMoments] = {}, r[kTerms] = {};
  for (int j = 0; j < most; ++j)
    add_point<Lo, Hi>(at(&LaneGroup::u, j) * inv, at(&LaneGroup::v, j) * inv, at(&LaneGroup::d, j), m, r);
  static constexpr GramIndex<Lo, Hi> index{};
  SmallLdltLanes<kTerms, V> ldlt;
  bool factored[kLanes];
  ldlt.factor(m, index.at, factored);
  V c[kTerms];
  ldlt.solve(r, c);
  // finish()'s test of every coefficient, in the lanes: a non-finite
  // entry has all exponent bits set, so adding 2^52 to its exponent field
  // sets the top bit (integer arithmetic: no mask built lane by lane).
  using Bits = std::conditional_t<G == 1, Bits4, Bits8>;
  Bits infinite = {};
  for (int i = 0; i < kTerms; ++i) infinite |= ((Bits)c[i] & 0x7FF0000000000000u) + (uint64_t(1) << 52);
  for (int l = 0; l < kLanes; ++l) {
    if (!live[l]) continue;
    HeightFit& o = out[l / 4][l % 4];
    if (!factored[l]) {
      o = fit_lane_alone<Lo, Hi>(group[l / 4], l % 4, min_rcond);
      continue;
    }
    if (conditioned<kTerms>([&](int i) { return ldlt.d(l, i); }, min_rcond, o) && !(infinite[l] >> 63)) {
      double first[5];  // the linear and quadratic coefficients
      for (int i = 0; i < std::min(5, kTerms); ++i) first[i] = c[i][l];
      derivatives<Lo, Hi>(first, scale[l], o);
    }
  }
}

template <int Lo, int Hi>
HeightFit fit_plain(const double* u, const double* v, const double* d, int count, double min_rcond) {
  return fit_body<Lo, Hi>(u, v, d, count, min_rcond);
}

// The same code built for AVX, and for AVX-512 (whose 32 vector registers
// hold the quartic's 56 sums with fewer spills), where the build's baseline
// lacks them, chosen at run time: the same operations on 4 lanes, so the
// same bits (no fused multiply-add: this file is built with
// -ffp-contract=off, see CMakeLists.txt).
#ifdef ISOFORM_AVX_CLONE
template <int Lo, int Hi>
ISOFORM_AVX_TARGET HeightFit fit_avx(const double* u, const double* v, const double* d, int count,
                                     double min_rcond) {
  return fit_body<Lo, Hi>(u, v, d, count, min_rcond);
}
template <int Lo, int Hi>
ISOFORM_AVX_TARGET void fit_lanes_avx(const LaneGroup* group, double min_rcond, HeightFit (*out)[4]) {
  fit_lanes_body<Lo, Hi, 1>(group, min_rcond, out);
}
template <int Lo, int Hi>
ISOFORM_AVX512_TARGET HeightFit fit_avx512(const double* u, const double* v, const double* d, int count,
                                           double min_rcond) {
  return fit_body<Lo, Hi>(u, v, d, count, min_rcond);
}
template <int Lo, int Hi, int G>
ISOFORM_AVX512_TARGET void fit_lanes_avx512(const LaneGroup* group, double min_rcond, HeightFit (*out)[4]) {
  fit_lanes_body<Lo, Hi, G>(group, min_rcond, out);
}

#endif

template <int Lo, int Hi>
void fit_lanes_plain(const LaneGroup* group, double min_rcond, HeightFit (*out)[4]) {
  fit_lanes_body<Lo, Hi, 1>(group, min_rcond, out);
}

// G groups: with AVX-512 all in one vector (G = 2: eight lanes), else one
// group after another.
template <int Lo, int Hi, int G>
void fit_lanes(const LaneGroup* group, double min_rcond, HeightFit (*out)[4]) {
#ifdef ISOFORM_AVX_CLONE
  if (vector_level() == 2) return fit_lanes_avx512<Lo, Hi, G>(group, min_rcond, out);
#endif
  for (int g = 0; g < G; ++g) {
#ifdef ISOFORM_AVX_CLONE
    if (vector_level() == 1) {
      fit_lanes_avx<Lo, Hi>(group + g, min_rcond, out + g);
      continue;
    }
#endif
    fit_lanes_plain<Lo, Hi>(group + g, min_rcond, out + g);
  }
}

template <int G>
void fit_groups(FitModel model, const LaneGroup* group, double min_rcond, HeightFit (*out)[4]) {
  switch (model) {
    case FitModel::SeedQuadratic: return fit_lanes<2, 2, G>(group, min_rcond, out);
    case FitModel::Quadric: return fit_lanes<1, 2, G>(group, min_rcond, out);
    case FitModel::Cubic: return fit_lanes<1, 3, G>(group, min_rcond, out);
    case FitModel::Quartic: return fit_lanes<1, 4, G>(group, min_rcond, out);
  }
}

template <int Lo, int Hi>
HeightFit fit(const double* u, const double* v, const double* d, int count, double min_rcond) {
#ifdef ISOFORM_AVX_CLONE
  switch (vector_level()) {
    case 2: return fit_avx512<Lo, Hi>(u, v, d, count, min_rcond);
    case 1: return fit_avx<Lo, Hi>(u, v, d, count, min_rcond);
    default: break;
  }
#endif
  return fit_plain<Lo, Hi>(u, v, d, count, min_rcond);
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

void fit_height_lanes(FitModel model, const double* u, const double* v, const double* d, const int (&count)[4],
                      HeightFit (&out)[4], double min_rcond) {
  const LaneGroup group = {u, v, d, {count[0], count[1], count[2], count[3]}};
  fit_groups<1>(model, &group, min_rcond, &out);
}

void fit_height_lanes(FitModel model, const LaneGroup (&groups)[2], HeightFit (&out)[2][4], double min_rcond) {
  fit_groups<2>(model, groups, min_rcond, out);
}

}  // namespace isoform

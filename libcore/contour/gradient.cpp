// Zucker-Hummel gradient estimates (Hamann 1991, Theorem 3.8).
#include "gradient.h"

#include <cmath>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace isoform {
namespace {

// Value at (i+r, j+s, k+t). Where that sample is undefined (past the face
// of a dense array, whose defined samples form a box), the offsets that leave
// the box are dropped and f is continued linearly along those axes with the
// backward difference at (i, j, k): exact for linear f.
double neighbour(const Brick& b, int i, int j, int k, int r, int s, int t) {
  if (b.is_defined(i + r, j + s, k + t)) return b.value(i + r, j + s, k + t);
  const int d[3] = {r, s, t};
  int kept[3] = {r, s, t};
  const double centre = b.value(i, j, k);
  double slope_sum = 0.0;
  for (int a = 0; a < 3; ++a) {
    if (d[a] == 0) continue;
    const int step[3] = {a == 0 ? d[a] : 0, a == 1 ? d[a] : 0, a == 2 ? d[a] : 0};
    if (b.is_defined(i + step[0], j + step[1], k + step[2])) continue;
    kept[a] = 0;
    if (b.is_defined(i - step[0], j - step[1], k - step[2]))
      slope_sum += centre - b.value(i - step[0], j - step[1], k - step[2]);
  }
  return b.value(i + kept[0], j + kept[1], k + kept[2]) + slope_sum;
}

}  // namespace

namespace {
const double kWeight[4] = {0.0, 1.0, 1.0 / std::sqrt(2.0), 1.0 / std::sqrt(3.0)};
const double kNorm = 2.0 * (1.0 + 4.0 / std::sqrt(2.0) + 4.0 / std::sqrt(3.0));
}  // namespace

Vec3d zucker_hummel_inside(const float* at, size_t row, size_t slice) {
  // The sums of zucker_hummel() grouped by axis: for x, the weighted
  // differences f(i+1, j+s, k+t) - f(i-1, j+s, k+t) over the 9 (s, t), and
  // likewise for y and z; the terms with a zero offset along the axis drop.
  const std::ptrdiff_t dx = 1, dy = std::ptrdiff_t(row), dz = std::ptrdiff_t(slice);
#if defined(__SSE2__)
  // x and y side by side in one register: each lane takes the same steps,
  // each rounded as the scalar ones are, so the sums are the same bits.
  __m128d gxy = _mm_setzero_pd();
#else
  double gx = 0.0, gy = 0.0;
#endif
  double gz = 0.0;
  for (int u = -1; u <= 1; ++u)
    for (int v = -1; v <= 1; ++v) {
      const double w = kWeight[1 + std::abs(u) + std::abs(v)];
      const float* px = at + u * dy + v * dz;  // (s, t) = (u, v)
      const float* py = at + u * dx + v * dz;  // (r, t) = (u, v)
      const float* pz = at + u * dx + v * dy;  // (r, s) = (u, v)
#if defined(__SSE2__)
      const __m128d hi = _mm_cvtps_pd(_mm_unpacklo_ps(_mm_load_ss(px + dx), _mm_load_ss(py + dy)));
      const __m128d lo = _mm_cvtps_pd(_mm_unpacklo_ps(_mm_load_ss(px - dx), _mm_load_ss(py - dy)));
      gxy = _mm_add_pd(gxy, _mm_mul_pd(_mm_set1_pd(w), _mm_sub_pd(hi, lo)));
#else
      gx += w * (double(px[dx]) - double(px[-dx]));
      gy += w * (double(py[dy]) - double(py[-dy]));
#endif
      gz += w * (double(pz[dz]) - double(pz[-dz]));
    }
#if defined(__SSE2__)
  double g[2];
  _mm_storeu_pd(g, _mm_div_pd(gxy, _mm_set1_pd(kNorm)));
  return {g[0], g[1], gz / kNorm};
#else
  return {gx / kNorm, gy / kNorm, gz / kNorm};
#endif
}

Vec3d zucker_hummel(const Brick& b, int i, int j, int k) {
  // NOTE: c = sqrt(n) / n with n = |r| + |s| + |t|, so 1, 1/sqrt(2),
  // 1/sqrt(3). For f = x the x-sum is 2 (1 + 4/sqrt(2) + 4/sqrt(3)); dividing
  // by it makes the estimate exact on linear functions, which the seed's
  // normalisation to unit length does not need but later chapters use.
  static const double w[4] = {0.0, 1.0, 1.0 / std::sqrt(2.0), 1.0 / std::sqrt(3.0)};
  static const double norm = 2.0 * (1.0 + 4.0 / std::sqrt(2.0) + 4.0 / std::sqrt(3.0));
  Vec3d grad{0.0, 0.0, 0.0};
  for (int t = -1; t <= 1; ++t)
    for (int s = -1; s <= 1; ++s)
      for (int r = -1; r <= 1; ++r) {
        const int n = std::abs(r) + std::abs(s) + std::abs(t);
        if (n == 0) continue;
        const double fv = w[n] * neighbour(b, i, j, k, r, s, t);
        grad[0] += r * fv;
        grad[1] += s * fv;
        grad[2] += t * fv;
      }
  for (double& c : grad) c /= norm;
  return grad;
}

}  // namespace isoform

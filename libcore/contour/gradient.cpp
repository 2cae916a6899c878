// Zucker-Hummel gradient estimates (Hamann 1991, Theorem 3.8).
#include "gradient.h"

#include <cmath>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif
#if defined(__x86_64__) && defined(__GNUC__)
#include <immintrin.h>
#define ISOFORM_ZH_FOUR 1
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

#if defined(ISOFORM_ZH_FOUR)
bool has_zucker_hummel_four() {
  static const bool avx = __builtin_cpu_supports("avx");
  return avx;
}

// NOTE: lane l is sample at + l: every lane takes the scalar steps of
// zucker_hummel_inside() in its order (no fused multiply-add: the target is
// AVX alone), so each gradient is the same to the bit.
namespace {

// f(x + step) - f(x - step) at the four samples from p, as doubles.
__attribute__((target("avx"))) inline __m256d four_differences(const float* p, std::ptrdiff_t step) {
  return _mm256_sub_pd(_mm256_cvtps_pd(_mm_loadu_ps(p + step)), _mm256_cvtps_pd(_mm_loadu_ps(p - step)));
}

}  // namespace

__attribute__((target("avx"))) void zucker_hummel_four(const float* at, size_t row, size_t slice, Vec3d out[4]) {
  const std::ptrdiff_t dy = std::ptrdiff_t(row), dz = std::ptrdiff_t(slice);
  __m256d gx = _mm256_setzero_pd(), gy = _mm256_setzero_pd(), gz = _mm256_setzero_pd();
  for (int u = -1; u <= 1; ++u)
    for (int v = -1; v <= 1; ++v) {
      const __m256d w = _mm256_set1_pd(kWeight[1 + std::abs(u) + std::abs(v)]);
      gx = _mm256_add_pd(gx, _mm256_mul_pd(w, four_differences(at + u * dy + v * dz, 1)));
      gy = _mm256_add_pd(gy, _mm256_mul_pd(w, four_differences(at + u + v * dz, dy)));
      gz = _mm256_add_pd(gz, _mm256_mul_pd(w, four_differences(at + u + v * dy, dz)));
    }
  const __m256d norm = _mm256_set1_pd(kNorm);
  double x[4], y[4], z[4];
  _mm256_storeu_pd(x, _mm256_div_pd(gx, norm));
  _mm256_storeu_pd(y, _mm256_div_pd(gy, norm));
  _mm256_storeu_pd(z, _mm256_div_pd(gz, norm));
  for (int l = 0; l < 4; ++l) out[l] = {x[l], y[l], z[l]};
}
#else
bool has_zucker_hummel_four() { return false; }
void zucker_hummel_four(const float* at, size_t row, size_t slice, Vec3d out[4]) {
  for (int l = 0; l < 4; ++l) out[l] = zucker_hummel_inside(at + l, row, slice);
}
#endif

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

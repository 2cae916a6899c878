// Robust ranges and the two colour maps of curvature pictures.
#include "curvature_colours.h"

#include <algorithm>
#include <cmath>

#include "../errors.h"
#include "../fresh_memory.h"
#include "float_ranks.h"
#include "vector_level.h"

namespace isoform {
namespace {

struct Rgb {
  double r, g, b;
};

// Piecewise-linear colour maps through a few control colours, t in [0, 1].
Rgb lerp_map(const Rgb* stops, int count, double t) {
  t = (t > 0.0 ? std::min(t, 1.0) : 0.0) * (count - 1);  // NaN to 0: never an index
  const int i = std::min(count - 2, int(t));
  const double f = t - i;
  return {stops[i].r + f * (stops[i + 1].r - stops[i].r), stops[i].g + f * (stops[i + 1].g - stops[i].g),
          stops[i].b + f * (stops[i + 1].b - stops[i].b)};
}

// Blue through white to red: negative, zero, positive.
const Rgb* diverging_stops() {
  static const Rgb stops[] = {{0.23, 0.30, 0.75}, {0.55, 0.69, 1.00}, {0.87, 0.87, 0.87},
                              {0.96, 0.60, 0.48}, {0.71, 0.02, 0.15}};
  return stops;
}
Rgb diverging(double t) { return lerp_map(diverging_stops(), 5, t); }

// Dark violet through green to yellow.
const Rgb* sequential_stops() {
  static const Rgb stops[] = {{0.267, 0.005, 0.329}, {0.230, 0.322, 0.546}, {0.128, 0.567, 0.551},
                              {0.369, 0.789, 0.383}, {0.993, 0.906, 0.144}};
  return stops;
}
Rgb sequential(double t) { return lerp_map(sequential_stops(), 5, t); }

bool usable(uint8_t flags) { return !(flags & (kCurvatureIsolated | kCurvatureFailed)); }

// std::lround(255 c) for c in [0, 1] (the maps' channels), without the
// library call: for x >= 0, x - trunc(x) is exact, so the comparison with
// one half rounds halves away from zero as lround does.
uint8_t channel(double c) {
  const double x = 255.0 * c;
  if (!(x >= 0.0)) return 0;
  const int whole = int(x);
  return uint8_t(x - double(whole) >= 0.5 ? whole + 1 : whole);
}

}  // namespace

const std::vector<float>& curvature_values(const VertexCurvature& c, CurvatureQuantity q) {
  switch (q) {
    case CurvatureQuantity::K1: return c.k1;
    case CurvatureQuantity::K2: return c.k2;
    case CurvatureQuantity::Mean: return c.mean;
    case CurvatureQuantity::Gauss: return c.gauss;
    case CurvatureQuantity::Absolute: return c.absolute;
  }
  throw InvalidArgument("curvature colours: unknown quantity");
}

const std::vector<float>& curvature_values(const Mesh& mesh, CurvatureQuantity q) {
  if (mesh.curvature.empty() && mesh.vertex_count() > 0)
    throw InvalidArgument("curvature colours: the mesh has no curvature");
  return curvature_values(mesh.curvature, q);
}

namespace {

void colour_range(const VertexCurvature& c, CurvatureQuantity q, double* lo, double* hi) {
  const std::vector<float>& values = curvature_values(c, q);
  const uint8_t* flags = c.flags.data();
  // The 2nd and 98th percentiles of the usable vertices' finite values.
  const float* data = values.data();
  const auto ranks =
      float_ranks(data, values.size(), [flags, data](size_t v) { return usable(flags[v]) && std::isfinite(data[v]); });
  const size_t n = ranks.count();
  auto rank = [n](double f) { return std::min(n - 1, size_t(f * double(n - 1) + 0.5)); };
  float at_lo = 0, at_hi = 0;
  if (n > 0) ranks.at(rank(0.02), rank(0.98), &at_lo, &at_hi);
  *lo = at_lo;
  *hi = at_hi;
  if (q != CurvatureQuantity::Absolute) {
    const double m = std::max(std::abs(*lo), std::abs(*hi));
    *lo = -m;
    *hi = m;
  }
}

// The colour of W vertices at once (2: the baseline's vector registers, 4:
// AVX's), each lane with the bits of curvature_colour: the same operations
// on doubles lane by lane, the map's segment chosen by comparisons (int(t)
// for t in [0, 4]), the channel rounded as channel() rounds it.
template <int W>
struct Lanes {
  typedef double D __attribute__((vector_size(8 * W)));
  typedef int64_t M __attribute__((vector_size(8 * W)));
};

template <class D>
inline __attribute__((always_inline)) D splat(double x) {
  return D{} + x;
}

template <class D, class M>
inline __attribute__((always_inline)) D pick(M c, D a, D b) {
  return (D)((c & (M)a) | (~c & (M)b));
}

// Segment i's start and its step to the next stop, per channel.
struct Segments {
  double base[3][4], step[3][4];
  explicit Segments(const Rgb* stops) {
    for (int i = 0; i < 4; ++i) {
      const double from[3] = {stops[i].r, stops[i].g, stops[i].b}, to[3] = {stops[i + 1].r, stops[i + 1].g, stops[i + 1].b};
      for (int k = 0; k < 3; ++k) {
        base[k][i] = from[k];
        step[k][i] = to[k] - from[k];
      }
    }
  }
};

template <class D, class M>
inline __attribute__((always_inline)) D segment(const double (&s)[4], M m1, M m2, M m3) {
  return pick(m3, splat<D>(s[3]), pick(m2, splat<D>(s[2]), pick(m1, splat<D>(s[1]), splat<D>(s[0]))));
}

// channel() for every lane, lane l into byte 4 l of out. For 0 <= x < 2^51,
// x + 2^52 rounds x to an integer in the low bits of its significand, and
// one less where that rounded up gives int(x); all exact.
template <int W>
inline __attribute__((always_inline)) void channels(typename Lanes<W>::D c, uint8_t* out) {
  typedef typename Lanes<W>::D D;
  typedef typename Lanes<W>::M M;
  const D x = 255.0 * c, big = splat<D>(4503599627370496.0);  // 2^52
  D whole = (x + big) - big;
  whole -= (D)((M)(whole > x) & (M)splat<D>(1.0));
  const D rounded = whole + (D)((M)(x - whole >= splat<D>(0.5)) & (M)splat<D>(1.0));
  const M bits = (M)(rounded + big) & (M)(x >= splat<D>(0.0));  // 0 where x < 0 or NaN
  for (int l = 0; l < W; ++l) out[4 * l] = uint8_t(bits[l]);
}

template <int W>
inline __attribute__((always_inline)) void colour_lanes(const float* values, const uint8_t* flags, bool absolute,
                                                        double lo, double hi, double span, const Segments& map,
                                                        uint8_t* out) {
  typedef typename Lanes<W>::D D;
  typedef typename Lanes<W>::M M;
  D t, zero = splat<D>(0.0), one = splat<D>(1.0);
  M grey;
  for (int l = 0; l < W; ++l) {
    t[l] = values[l];
    grey[l] = -int64_t(!usable(flags[l]) || !std::isfinite(values[l]) || !std::isfinite(lo) || !std::isfinite(hi));
  }
  t = (t - lo) / span;
  if (!absolute && !(hi > lo)) t = splat<D>(0.5);
  // lerp_map: clamp to [0, 1] as std::clamp does, times 4, segment and fraction.
  t = pick(t < zero, zero, pick(one < t, one, t)) * 4.0;
  const M m1 = t >= 1.0, m2 = t >= 2.0, m3 = t >= 3.0;
  const D f = t - pick(m3, splat<D>(3.0), pick(m2, splat<D>(2.0), pick(m1, one, zero)));
  for (int k = 0; k < 3; ++k) {
    const D c = segment<D>(map.base[k], m1, m2, m3) + f * segment<D>(map.step[k], m1, m2, m3);
    channels<W>(pick(grey, splat<D>(0.5), c), out + k);
  }
  for (int l = 0; l < W; ++l) out[4 * l + 3] = 255;
}

// Vertices first .. last - 1 (a multiple of W of them).
template <int W>
inline __attribute__((always_inline)) void fill_body(const float* values, const uint8_t* flags, size_t first,
                                                     size_t last, bool absolute, double lo, double hi, double span,
                                                     const Segments& map, uint8_t* colors) {
  for (size_t v = first; v < last; v += W)
    colour_lanes<W>(values + v, flags + v, absolute, lo, hi, span, map, colors + 4 * v);
}

void fill_plain(const float* values, const uint8_t* flags, size_t first, size_t last, bool absolute, double lo,
                double hi, double span, const Segments& map, uint8_t* colors) {
  fill_body<2>(values, flags, first, last, absolute, lo, hi, span, map, colors);
}

#ifdef ISOFORM_AVX_CLONE
ISOFORM_AVX_TARGET void fill_avx(const float* values, const uint8_t* flags, size_t first, size_t last,
                                 bool absolute, double lo, double hi, double span, const Segments& map,
                                 uint8_t* colors) {
  fill_body<4>(values, flags, first, last, absolute, lo, hi, span, map, colors);
}
#endif

void fill_colours(const VertexCurvature& c, CurvatureQuantity q, double lo, double hi, std::vector<uint8_t>& colors) {
  const std::vector<float>& values = curvature_values(c, q);
  const double span = hi > lo ? hi - lo : 1.0;
  if (colors.size() != 4 * values.size()) {  // new pages made present first (fresh_memory.h)
    colors.clear();
    colors.shrink_to_fit();
    fresh_resize(colors, 4 * values.size(), false, true);
  }
  const bool absolute = q == CurvatureQuantity::Absolute;
  static const Segments diverging_map(diverging_stops()), sequential_map(sequential_stops());
  const Segments& map = absolute ? sequential_map : diverging_map;
  const size_t n = values.size();
  size_t v = 0;
#ifdef ISOFORM_AVX_CLONE
  if (vector_level() > 0) {
    fill_avx(values.data(), c.flags.data(), 0, n / 4 * 4, absolute, lo, hi, span, map, colors.data());
    v = n / 4 * 4;
  }
#endif
  fill_plain(values.data(), c.flags.data(), v, v + (n - v) / 2 * 2, absolute, lo, hi, span, map, colors.data());
  for (v += (n - v) / 2 * 2; v < n; ++v) curvature_colour(q, lo, hi, values[v], c.flags[v], &colors[4 * v]);
}

}  // namespace

void curvature_colour(CurvatureQuantity q, double lo, double hi, float value, uint8_t flags, uint8_t* out) {
  // A value that is not a number is shown as unusable: grey, as the flags
  // say; it never reaches the map, whose segment index it would be.
  Rgb rgb = {0.5, 0.5, 0.5};
  if (usable(flags) && std::isfinite(value) && std::isfinite(lo) && std::isfinite(hi)) {
    const double span = hi > lo ? hi - lo : 1.0;
    const double t = (value - lo) / span;
    rgb = q == CurvatureQuantity::Absolute ? sequential(t) : diverging(hi > lo ? t : 0.5);
  }
  out[0] = channel(rgb.r);
  out[1] = channel(rgb.g);
  out[2] = channel(rgb.b);
  out[3] = 255;
}

void curvature_colour_range(const Mesh& mesh, CurvatureQuantity q, double* lo, double* hi) {
  curvature_values(mesh, q);  // checks that there is curvature
  colour_range(mesh.curvature, q, lo, hi);
}

void colour_by_curvature(Mesh& mesh, CurvatureQuantity q) {
  double lo, hi;
  curvature_colour_range(mesh, q, &lo, &hi);
  fill_colours(mesh.curvature, q, lo, hi, mesh.colors);
}

void curvature_colours(const VertexCurvature& c, CurvatureQuantity q, std::vector<uint8_t>& colors, double* lo,
                       double* hi) {
  colour_range(c, q, lo, hi);
  fill_colours(c, q, *lo, *hi, colors);
}

}  // namespace isoform

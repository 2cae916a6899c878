// Robust ranges and the two colour maps of curvature pictures.
#include "curvature_colours.h"

#include <algorithm>
#include <cmath>

#include "../errors.h"

namespace isoform {
namespace {

struct Rgb {
  double r, g, b;
};

// Piecewise-linear colour maps through a few control colours, t in [0, 1].
Rgb lerp_map(const Rgb* stops, int count, double t) {
  t = std::clamp(t, 0.0, 1.0) * (count - 1);
  const int i = std::min(count - 2, int(t));
  const double f = t - i;
  return {stops[i].r + f * (stops[i + 1].r - stops[i].r), stops[i].g + f * (stops[i + 1].g - stops[i].g),
          stops[i].b + f * (stops[i + 1].b - stops[i].b)};
}

// Blue through white to red: negative, zero, positive.
Rgb diverging(double t) {
  static const Rgb stops[] = {{0.23, 0.30, 0.75}, {0.55, 0.69, 1.00}, {0.87, 0.87, 0.87},
                              {0.96, 0.60, 0.48}, {0.71, 0.02, 0.15}};
  return lerp_map(stops, 5, t);
}

// Dark violet through green to yellow.
Rgb sequential(double t) {
  static const Rgb stops[] = {{0.267, 0.005, 0.329}, {0.230, 0.322, 0.546}, {0.128, 0.567, 0.551},
                              {0.369, 0.789, 0.383}, {0.993, 0.906, 0.144}};
  return lerp_map(stops, 5, t);
}

// The p-th and q-th percentiles (p <= q) of v, which is reordered.
void percentiles(std::vector<float>& v, double p, double q, double* at_p, double* at_q) {
  if (v.empty()) {
    *at_p = *at_q = 0.0;
    return;
  }
  auto rank = [&](double f) { return std::min(v.size() - 1, size_t(f * double(v.size() - 1) + 0.5)); };
  const size_t kp = rank(p), kq = rank(q);
  std::nth_element(v.begin(), v.begin() + long(kq), v.end());
  *at_q = v[kq];
  // Everything before kq is at most v[kq]: the kp-th smallest is among it.
  if (kp < kq) std::nth_element(v.begin(), v.begin() + long(kp), v.begin() + long(kq));
  *at_p = v[kp];
}

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
  std::vector<float> kept(values.size());
  size_t count = 0;
  for (size_t v = 0; v < values.size(); ++v)
    if (usable(c.flags[v])) kept[count++] = values[v];
  kept.resize(count);
  percentiles(kept, 0.02, 0.98, lo, hi);
  if (q != CurvatureQuantity::Absolute) {
    const double m = std::max(std::abs(*lo), std::abs(*hi));
    *lo = -m;
    *hi = m;
  }
}

void fill_colours(const VertexCurvature& c, CurvatureQuantity q, double lo, double hi, std::vector<uint8_t>& colors) {
  const std::vector<float>& values = curvature_values(c, q);
  const double span = hi > lo ? hi - lo : 1.0;
  colors.resize(4 * values.size());
  for (size_t v = 0; v < values.size(); ++v) {
    const double t = (values[v] - lo) / span;
    Rgb rgb = q == CurvatureQuantity::Absolute ? sequential(t) : diverging(hi > lo ? t : 0.5);
    if (!usable(c.flags[v])) rgb = {0.5, 0.5, 0.5};
    uint8_t* out = &colors[4 * v];
    out[0] = channel(rgb.r);
    out[1] = channel(rgb.g);
    out[2] = channel(rgb.b);
    out[3] = 255;
  }
}

}  // namespace

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

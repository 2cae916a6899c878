// Table 4.2's functions, exact curvatures and RMS errors.
#include "graph_table.h"

#include <cmath>

#include "libcore/curvature/graph_block.h"

namespace isoform::table42 {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kSpacing = 1.0 / 12.5;

double linear(double x, double y, double z) { return .2 * (x + y + z); }
void linear_d(double, double, double, double d[9]) {
  const double v[9] = {.2, .2, .2, 0, 0, 0, 0, 0, 0};
  std::copy(v, v + 9, d);
}
double q1(double x, double y, double z) { return .4 * (x * x + y * y + z * z); }
void q1_d(double x, double y, double z, double d[9]) {
  const double v[9] = {.8 * x, .8 * y, .8 * z, .8, 0, 0, .8, 0, .8};
  std::copy(v, v + 9, d);
}
double q2(double x, double y, double z) { return .4 * (x * x - y * y - z * z); }
void q2_d(double x, double y, double z, double d[9]) {
  const double v[9] = {.8 * x, -.8 * y, -.8 * z, .8, 0, 0, -.8, 0, -.8};
  std::copy(v, v + 9, d);
}
// .15 (x^3 + 2 x^2 y - x z^2 + 2 y^2)
double cubic(double x, double y, double z) { return .15 * (x * x * x + 2 * x * x * y - x * z * z + 2 * y * y); }
void cubic_d(double x, double y, double z, double d[9]) {
  const double v[9] = {.15 * (3 * x * x + 4 * x * y - z * z), .15 * (2 * x * x + 4 * y), .15 * (-2 * x * z),
                       .15 * (6 * x + 4 * y), .15 * (4 * x), .15 * (-2 * z), .15 * 4, 0, .15 * (-2 * x)};
  std::copy(v, v + 9, d);
}
double cosine(double x, double y, double z) { return .1 * (std::cos(kPi * x) + std::cos(kPi * y) + std::cos(kPi * z)); }
void cosine_d(double x, double y, double z, double d[9]) {
  const double s = .1 * kPi, c = .1 * kPi * kPi;
  const double v[9] = {-s * std::sin(kPi * x), -s * std::sin(kPi * y), -s * std::sin(kPi * z),
                       -c * std::cos(kPi * x), 0, 0, -c * std::cos(kPi * y), 0, -c * std::cos(kPi * z)};
  std::copy(v, v + 9, d);
}

double coordinate(int i) { return -1.0 + i / 12.5; }

}  // namespace

const std::vector<Function>& functions() {
  static const std::vector<Function> all = {
      {".2(x+y+z)", linear, linear_d},
      {".4(x^2+y^2+z^2)", q1, q1_d},
      {".4(x^2-y^2-z^2)", q2, q2_d},
      {".15(x^3+2x^2y-xz^2+2y^2)", cubic, cubic_d},
      {".1(cos(pi x)+cos(pi y)+cos(pi z))", cosine, cosine_d},
  };
  return all;
}

Errors measure(const Function& f, Column column) {
  const int n = kGridPoints;
  GraphBlock block;
  block.reset({0, 0, 0}, {n, n, n});
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) block.set({i, j, k}, f.value(coordinate(i), coordinate(j), coordinate(k)));
  // The seed's grid: index (i, j, k) at world (-1 + i / 12.5, ...).
  const GraphAxes axes = GraphAxes::of(Affine::scale_translate({kSpacing, kSpacing, kSpacing}, {-1, -1, -1}));
  Errors e;
  double sum[4] = {0, 0, 0, 0};
  long long all = 0, interior = 0;
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const double x = coordinate(i), y = coordinate(j), z = coordinate(k);
        double d[9];
        f.derivatives(x, y, z, d);
        const GraphPrincipal exact =
            graph_principal_from_derivatives({d[0], d[1], d[2]}, {{{d[3], d[4], d[5]}, {d[4], d[6], d[7]}, {d[5], d[7], d[8]}}});
        const GraphSamples s = block.samples({i, j, k});
        GraphCurvature c;
        if (column == Column::SeedExactGradient)
          c = graph_seed_curvature_with_gradient(s, axes, {d[0], d[1], d[2]});
        else
          c = graph_curvature_at(s, axes, column == Column::Seed ? GraphMethod::Seed : GraphMethod::Default);
        ++e.fits[size_t(c.fit)];
        const double dh = c.curvature.mean - exact.mean, dk = c.curvature.gauss - exact.gauss;
        sum[0] += dh * dh;
        sum[1] += dk * dk;
        ++all;
        const bool inner = i > 0 && j > 0 && k > 0 && i < n - 1 && j < n - 1 && k < n - 1;
        if (inner) {
          sum[2] += dh * dh;
          sum[3] += dk * dk;
          ++interior;
        }
      }
  e.rms_mean_all = std::sqrt(sum[0] / double(all));
  e.rms_gauss_all = std::sqrt(sum[1] / double(all));
  e.rms_mean_interior = std::sqrt(sum[2] / double(interior));
  e.rms_gauss_interior = std::sqrt(sum[3] / double(interior));
  return e;
}

}  // namespace isoform::table42

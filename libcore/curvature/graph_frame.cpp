// Gram-Schmidt tangent frame of a graph in R^4 (Section 4.3).
#include "graph_frame.h"

#include <cmath>

namespace isoform {
namespace {

double dot(const Vec4d& a, const Vec4d& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + a[3] * b[3]; }

}  // namespace

GraphFrame graph_frame(const std::array<double, 3>& g) {
  GraphFrame f;
  const double l = std::sqrt(1.0 + g[0] * g[0] + g[1] * g[1] + g[2] * g[2]);
  f.n = {-g[0] / l, -g[1] / l, -g[2] / l, 1.0 / l};
  // b_i = a_i minus its components along n and the earlier b's, normalised.
  // a_1, a_2, a_3 and n are independent (n's last component is 1/l > 0), so
  // no norm below vanishes.
  for (int i = 0; i < 3; ++i) {
    Vec4d a{0, 0, 0, 0};
    a[size_t(i)] = 1.0;
    Vec4d b = a;
    const double an = dot(a, f.n);
    for (int c = 0; c < 4; ++c) b[c] -= an * f.n[c];
    for (int j = 0; j < i; ++j) {
      const double ab = dot(a, f.b[size_t(j)]);
      for (int c = 0; c < 4; ++c) b[c] -= ab * f.b[size_t(j)][c];
    }
    const double len = std::sqrt(dot(b, b));
    for (int c = 0; c < 4; ++c) b[c] /= len;
    f.b[size_t(i)] = b;
  }
  return f;
}

GraphLocal graph_local(const GraphFrame& frame, const Vec4d& delta) {
  return {dot(delta, frame.b[0]), dot(delta, frame.b[1]), dot(delta, frame.b[2]), dot(delta, frame.n)};
}

}  // namespace isoform

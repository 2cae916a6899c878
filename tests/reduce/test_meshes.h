// Small meshes for the input-check tests: tori (closed, genus one) and flat
// grids, made by hand so that counts and indices can be checked.
#pragma once

#include <cmath>

#include "libcore/mesh.h"
#include "libcore/reduce/triangle_overlap.h"

namespace isoform::reduce {

// A torus ((R + r cos u) cos v, (R + r cos u) sin v, r sin u) around c.
inline void add_torus(Mesh& m, int nu, int nv, double R, double r, Point3 c) {
  const int32_t base = int32_t(m.vertex_count());
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i) {
      const double u = 2 * M_PI * i / nu, v = 2 * M_PI * j / nv;
      m.points.push_back(float(c[0] + (R + r * std::cos(u)) * std::cos(v)));
      m.points.push_back(float(c[1] + (R + r * std::cos(u)) * std::sin(v)));
      m.points.push_back(float(c[2] + r * std::sin(u)));
    }
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i) {
      const int32_t a = base + j * nu + i, b = base + j * nu + (i + 1) % nu,
                    d = base + ((j + 1) % nv) * nu + (i + 1) % nu, e = base + ((j + 1) % nv) * nu + i;
      m.triangles.insert(m.triangles.end(), {a, d, b, a, e, d});
    }
}

// An n x n grid of the plane z = 0 over [0, n - 1]^2, counter-clockwise.
inline Mesh plane_grid(int n) {
  Mesh m;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) m.points.insert(m.points.end(), {float(i), float(j), 0.0f});
  for (int j = 0; j + 1 < n; ++j)
    for (int i = 0; i + 1 < n; ++i) {
      const int32_t a = j * n + i;
      m.triangles.insert(m.triangles.end(), {a, a + 1, a + n + 1, a, a + n + 1, a + n});
    }
  return m;
}

}  // namespace isoform::reduce

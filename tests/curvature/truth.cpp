// Exact curvature of the test surfaces, and their triangulations.
#include "truth.h"

#include <cmath>
#include <map>
#include <random>

namespace isoform::truth {
namespace {

const double kPi = 3.14159265358979323846;

Exact from_h_k(double h, double k) {
  const double disc = std::sqrt(std::max(0.0, h * h - k));
  return {h + disc, h - disc};
}

void add_point(Mesh& m, double x, double y, double z) {
  m.points.push_back(float(x));
  m.points.push_back(float(y));
  m.points.push_back(float(z));
  m.precise_points.insert(m.precise_points.end(), {x, y, z});
}

}  // namespace

const std::vector<Graph>& table41_graphs() {
  static const std::vector<Graph> graphs = {
      {"plane", ".2(x+y)", [](double x, double y) { return .2 * (x + y); },
       [](double, double, double d[5]) { d[0] = .2, d[1] = .2, d[2] = d[3] = d[4] = 0; }, {0, 0, 0, 0}},
      {"cylinder", "sqrt(2-x^2)", [](double x, double) { return std::sqrt(2 - x * x); },
       [](double x, double, double d[5]) {
         const double s = std::sqrt(2 - x * x);
         d[0] = -x / s, d[1] = 0, d[2] = -2 / (s * s * s), d[3] = 0, d[4] = 0;
       },
       {.000291, .000035, .000132, .000025}},
      {"sphere", "sqrt(4-(x^2+y^2))", [](double x, double y) { return std::sqrt(4 - x * x - y * y); },
       [](double x, double y, double d[5]) {
         const double s = std::sqrt(4 - x * x - y * y), s3 = s * s * s;
         d[0] = -x / s, d[1] = -y / s, d[2] = -(4 - y * y) / s3, d[3] = -x * y / s3, d[4] = -(4 - x * x) / s3;
       },
       {.000159, .000046, .000080, .000080}},
      {"paraboloid", ".4(x^2+y^2)", [](double x, double y) { return .4 * (x * x + y * y); },
       [](double x, double y, double d[5]) { d[0] = .8 * x, d[1] = .8 * y, d[2] = .8, d[3] = 0, d[4] = .8; },
       {.003073, .001342, .001358, .001684}},
      {"hyperboloid", ".4(x^2-y^2)", [](double x, double y) { return .4 * (x * x - y * y); },
       [](double x, double y, double d[5]) { d[0] = .8 * x, d[1] = -.8 * y, d[2] = .8, d[3] = 0, d[4] = -.8; },
       {.002058, .002058, .001057, .001767}},
      {"monkey saddle", ".2(x^3-3xy^2)", [](double x, double y) { return .2 * (x * x * x - 3 * x * y * y); },
       [](double x, double y, double d[5]) {
         d[0] = .2 * (3 * x * x - 3 * y * y), d[1] = -1.2 * x * y, d[2] = 1.2 * x, d[3] = -1.2 * y, d[4] = -1.2 * x;
       },
       {.004483, .004483, .001591, .007247}},
      {"cubic polynomial", ".15(x^3+2x^2y-xy+2y^2)",
       [](double x, double y) { return .15 * (x * x * x + 2 * x * x * y - x * y + 2 * y * y); },
       [](double x, double y, double d[5]) {
         d[0] = .15 * (3 * x * x + 4 * x * y - y), d[1] = .15 * (2 * x * x - x + 4 * y);
         d[2] = .15 * (6 * x + 4 * y), d[3] = .15 * (4 * x - 1), d[4] = .15 * 4;
       },
       {.002258, .003598, .001665, .002242}},
      {"exponential", "exp(-(x^2+y^2)/2)", [](double x, double y) { return std::exp(-.5 * (x * x + y * y)); },
       [](double x, double y, double d[5]) {
         const double e = std::exp(-.5 * (x * x + y * y));
         d[0] = -x * e, d[1] = -y * e, d[2] = (x * x - 1) * e, d[3] = x * y * e, d[4] = (y * y - 1) * e;
       },
       {.001757, .005546, .002722, .002602}},
      {"trigonometric", ".1(cos(pi x)+cos(pi y))",
       [](double x, double y) { return .1 * (std::cos(kPi * x) + std::cos(kPi * y)); },
       [](double x, double y, double d[5]) {
         d[0] = -.1 * kPi * std::sin(kPi * x), d[1] = -.1 * kPi * std::sin(kPi * y);
         d[2] = -.1 * kPi * kPi * std::cos(kPi * x), d[3] = 0, d[4] = -.1 * kPi * kPi * std::cos(kPi * y);
       },
       {.002998, .002821, .001013, .003541}},
  };
  return graphs;
}

Exact graph_curvature(const Graph& g, double x, double y) {
  double d[5];
  g.derivatives(x, y, d);
  const double fx = d[0], fy = d[1], fxx = d[2], fxy = d[3], fyy = d[4];
  const double w = 1 + fx * fx + fy * fy, l = std::sqrt(w);
  // Positive where the graph bends away from its upward normal (fxx < 0).
  const double h = -((1 + fy * fy) * fxx - 2 * fx * fy * fxy + (1 + fx * fx) * fyy) / (2 * w * l);
  const double k = (fxx * fyy - fxy * fxy) / (w * w);
  return from_h_k(h, k);
}

Mesh graph_mesh(const Graph& g, int n) {
  Mesh m;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const double x = -1 + 2.0 * i / (n - 1), y = -1 + 2.0 * j / (n - 1);
      add_point(m, x, y, g.f(x, y));
    }
  for (int j = 0; j + 1 < n; ++j)
    for (int i = 0; i + 1 < n; ++i) {
      const int32_t a = j * n + i, b = a + 1, c = a + n + 1, d = a + n;
      m.triangles.insert(m.triangles.end(), {a, b, c, a, c, d});
    }
  return m;
}

const char* shape_name(Shape s) {
  switch (s) {
    case Shape::Sphere: return "sphere";
    case Shape::Torus: return "torus";
    case Shape::Ellipsoid: return "ellipsoid";
  }
  return "?";
}

namespace {

// The radii used for every shape: a unit sphere, a torus with R = 1 and
// r = 0.4, an ellipsoid with semi-axes 1, 0.7, 0.5.
constexpr double kTorusR = 1.0, kTorusr = 0.4;
constexpr double kAxes[3] = {1.0, 0.7, 0.5};

Exact ellipsoid_curvature(const double a[3], const double p[3]) {
  double h2 = 0, r2 = 0;
  for (int i = 0; i < 3; ++i) {
    h2 += p[i] * p[i] / (a[i] * a[i] * a[i] * a[i]);
    r2 += p[i] * p[i];
  }
  const double abc2 = a[0] * a[0] * a[1] * a[1] * a[2] * a[2], h = std::sqrt(h2);
  const double mean = (a[0] * a[0] + a[1] * a[1] + a[2] * a[2] - r2) / (2 * abc2 * h * h2);
  return from_h_k(mean, 1 / (abc2 * h2 * h2));
}

// An equal-angle cube sphere: six faces of q x q quads, projected to the
// unit sphere, jittered in the tangent plane and projected again, then
// scaled to the semi-axes.
Mesh cube_sphere(int q, double jitter, unsigned seed, const double axes[3], std::vector<Exact>& exact) {
  Mesh m;
  std::map<long long, int32_t> ids;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> uni(-1.0, 1.0);
  const double step = kPi / 2 / q;
  auto vertex = [&](int i, int j, int k) {
    const long long key = (static_cast<long long>(i) * (q + 1) + j) * (q + 1) + k;
    auto it = ids.find(key);
    if (it != ids.end()) return it->second;
    double c[3] = {std::tan(kPi / 4 * (2.0 * i / q - 1)), std::tan(kPi / 4 * (2.0 * j / q - 1)),
                   std::tan(kPi / 4 * (2.0 * k / q - 1))};
    double len = std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
    for (double& x : c) x /= len;
    for (double& x : c) x += jitter * step * uni(rng);
    len = std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
    double p[3];
    for (int a = 0; a < 3; ++a) p[a] = axes[a] * c[a] / len;
    add_point(m, p[0], p[1], p[2]);
    exact.push_back(ellipsoid_curvature(axes, p));
    return ids[key] = int32_t(m.vertex_count() - 1);
  };
  for (int axis = 0; axis < 3; ++axis)
    for (int side = 0; side <= q; side += q)
      for (int s = 0; s < q; ++s)
        for (int t = 0; t < q; ++t) {
          auto at = [&](int a, int b) {
            int ijk[3];
            ijk[axis] = side;
            ijk[(axis + 1) % 3] = a;
            ijk[(axis + 2) % 3] = b;
            return vertex(ijk[0], ijk[1], ijk[2]);
          };
          int32_t v[4] = {at(s, t), at(s + 1, t), at(s + 1, t + 1), at(s, t + 1)};
          // Outward when the face is the upper one of its axis.
          if (side == 0) std::swap(v[1], v[3]);
          m.triangles.insert(m.triangles.end(), {v[0], v[1], v[2], v[0], v[2], v[3]});
        }
  return m;
}

Mesh torus(int nu, int nv, double jitter, unsigned seed, std::vector<Exact>& exact) {
  Mesh m;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> uni(-1.0, 1.0);
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i) {
      const double u = 2 * kPi * (i + jitter * uni(rng)) / nu, v = 2 * kPi * (j + jitter * uni(rng)) / nv;
      const double w = kTorusR + kTorusr * std::cos(v);
      add_point(m, w * std::cos(u), w * std::sin(u), kTorusr * std::sin(v));
      exact.push_back({1 / kTorusr, std::cos(v) / w});
      if (exact.back().k2 > exact.back().k1) std::swap(exact.back().k1, exact.back().k2);
    }
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i) {
      const int32_t a = j * nu + i, b = j * nu + (i + 1) % nu, c = ((j + 1) % nv) * nu + (i + 1) % nu,
                    d = ((j + 1) % nv) * nu + i;
      m.triangles.insert(m.triangles.end(), {a, b, c, a, c, d});
    }
  return m;
}

}  // namespace

Mesh shape_mesh(Shape s, int resolution, double jitter, unsigned seed, std::vector<Exact>& exact) {
  exact.clear();
  const double unit[3] = {1, 1, 1};
  switch (s) {
    case Shape::Sphere: return cube_sphere(std::max(2, resolution / 4), jitter, seed, unit, exact);
    case Shape::Ellipsoid: return cube_sphere(std::max(2, resolution / 4), jitter, seed, kAxes, exact);
    case Shape::Torus:
      return torus(resolution, std::max(6, int(std::lround(resolution * kTorusr / kTorusR * 1.5))), jitter, seed,
                   exact);
  }
  return {};
}

std::vector<float> shape_normals(Shape s, const Mesh& mesh) {
  std::vector<float> n(mesh.points.size());
  for (size_t v = 0; v < mesh.vertex_count(); ++v) {
    const double x = mesh.points[3 * v], y = mesh.points[3 * v + 1], z = mesh.points[3 * v + 2];
    double g[3];
    if (s == Shape::Torus) {
      const double rho = std::hypot(x, y);
      g[0] = x - kTorusR * x / rho, g[1] = y - kTorusR * y / rho, g[2] = z;
    } else {
      const double unit[3] = {1, 1, 1};
      const double* a = s == Shape::Sphere ? unit : kAxes;
      g[0] = x / (a[0] * a[0]), g[1] = y / (a[1] * a[1]), g[2] = z / (a[2] * a[2]);
    }
    const double len = std::sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]);
    for (int a = 0; a < 3; ++a) n[3 * v + size_t(a)] = float(g[a] / len);
  }
  return n;
}

Rms rms_error(const Mesh& mesh, const std::vector<Exact>& exact, const std::vector<bool>& include) {
  Rms r;
  size_t count = 0;
  const VertexCurvature& c = mesh.curvature;
  for (size_t v = 0; v < exact.size(); ++v) {
    if (!include.empty() && !include[v]) continue;
    const double e1 = c.k1[v] - exact[v].k1, e2 = c.k2[v] - exact[v].k2;
    const double eh = c.mean[v] - exact[v].mean(), ek = c.gauss[v] - exact[v].gauss();
    r.k1 += e1 * e1, r.k2 += e2 * e2, r.mean += eh * eh, r.gauss += ek * ek;
    ++count;
  }
  if (count == 0) return r;
  for (double* x : {&r.k1, &r.k2, &r.mean, &r.gauss}) *x = std::sqrt(*x / double(count));
  return r;
}

}  // namespace isoform::truth

#include "libcore/curvature/surface_curvature.h"
#include "libcore/mesh_normals.h"

namespace isoform::truth {

Table41Row table41_row(const Graph& g, CurvatureMethod method, int n) {
  Mesh m = graph_mesh(g, n);
  estimate_normals(m);
  CurvatureOptions options;
  options.method = method;
  compute_curvature(m, options, Progress(nullptr));
  std::vector<Exact> exact;
  std::vector<bool> interior;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      exact.push_back(graph_curvature(g, -1 + 2.0 * i / (n - 1), -1 + 2.0 * j / (n - 1)));
      interior.push_back(i > 0 && j > 0 && i + 1 < n && j + 1 < n);
    }
  return {rms_error(m, exact), rms_error(m, exact, interior)};
}

}  // namespace isoform::truth

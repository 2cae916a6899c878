// patch_bench: evaluation speed of the side-vertex surface (points per
// second, one thread) on an icosphere of 20 * 4^k triangles with the sphere's
// normals: the point alone (double), point and exact normal (first-order
// jets), and everything with second derivatives (second-order jets). The same
// pseudo-random (triangle, u, v) samples for each mode; one run.
//
// usage: patch_bench [SUBDIVISIONS=4] [SAMPLES=1000000]
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <random>
#include <vector>

#include "libcore/patch/side_vertex_surface.h"
#include "libcore/topology.h"

namespace {

using isoform::Mesh;
using namespace isoform::patch;

Mesh icosphere(int levels) {
  const double g = (1 + std::sqrt(5.0)) / 2;
  std::vector<double> p = {-1, g, 0, 1, g, 0, -1, -g, 0, 1, -g, 0, 0, -1, g, 0, 1, g,
                           0, -1, -g, 0, 1, -g, g, 0, -1, g, 0, 1, -g, 0, -1, -g, 0, 1};
  std::vector<int32_t> t = {0, 11, 5, 0, 5, 1, 0, 1, 7, 0, 7, 10, 0, 10, 11, 1, 5, 9, 5, 11, 4, 11, 10, 2,
                            10, 7, 6, 7, 1, 8, 3, 9, 4, 3, 4, 2, 3, 2, 6, 3, 6, 8, 3, 8, 9, 4, 9, 5,
                            2, 4, 11, 6, 2, 10, 8, 6, 7, 9, 8, 1};
  auto normalise = [&](size_t i) {
    const double l = std::sqrt(p[3 * i] * p[3 * i] + p[3 * i + 1] * p[3 * i + 1] + p[3 * i + 2] * p[3 * i + 2]);
    for (int a = 0; a < 3; ++a) p[3 * i + a] /= l;
  };
  for (size_t i = 0; i < p.size() / 3; ++i) normalise(i);
  for (int l = 0; l < levels; ++l) {
    std::map<std::pair<int32_t, int32_t>, int32_t> mid;
    auto middle = [&](int32_t a, int32_t b) {
      const auto key = std::make_pair(std::min(a, b), std::max(a, b));
      const auto it = mid.find(key);
      if (it != mid.end()) return it->second;
      for (int k = 0; k < 3; ++k) p.push_back(p[3 * a + k] + p[3 * b + k]);
      normalise(p.size() / 3 - 1);
      return mid[key] = int32_t(p.size() / 3 - 1);
    };
    std::vector<int32_t> next;
    for (size_t i = 0; i < t.size(); i += 3) {
      const int32_t a = t[i], b = t[i + 1], c = t[i + 2];
      const int32_t ab = middle(a, b), bc = middle(b, c), ca = middle(c, a);
      next.insert(next.end(), {a, ab, ca, ab, b, bc, ca, bc, c, ab, bc, ca});
    }
    t = next;
  }
  Mesh m;
  m.precise_points = p;
  m.points.assign(p.begin(), p.end());
  m.normals = m.points;
  m.triangles = t;
  isoform::compute_topology(m);
  return m;
}

template <class F>
double rate(size_t n, F&& f) {
  const auto start = std::chrono::steady_clock::now();
  f();
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return double(n) / s;
}

}  // namespace

int main(int argc, char** argv) {
  const int levels = argc > 1 ? std::atoi(argv[1]) : 4;
  const size_t n = argc > 2 ? size_t(std::atoll(argv[2])) : 1000000;
  const Mesh m = icosphere(levels);
  PatchOptions o;
  const SideVertexSurface s(m, o);
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<size_t> tri(n);
  std::vector<double> uv(2 * n);
  for (size_t i = 0; i < n; ++i) {
    tri[i] = size_t(rng() % s.triangle_count());
    double u = unit(rng), v = unit(rng);
    if (u + v > 1) u = 1 - u, v = 1 - v;
    uv[2 * i] = u;
    uv[2 * i + 1] = v;
  }
  double sink = 0.0;
  const double points = rate(n, [&] {
    V3d p;
    for (size_t i = 0; i < n; ++i)
      if (s.point(tri[i], uv[2 * i], uv[2 * i + 1], p)) sink += p.x;
  });
  const double normals = rate(n, [&] {
    isoform::SurfaceSample x;
    for (size_t i = 0; i < n; ++i)
      if (s.evaluate_order(tri[i], uv[2 * i], uv[2 * i + 1], x, false)) sink += x.normal[0];
  });
  const double second = rate(n, [&] {
    isoform::SurfaceSample x;
    for (size_t i = 0; i < n; ++i)
      if (s.evaluate_order(tri[i], uv[2 * i], uv[2 * i + 1], x, true)) sink += x.duu[0];
  });
  std::printf("{\"triangles\": %zu, \"samples\": %zu, \"threads\": 1,\n", s.triangle_count(), n);
  std::printf(" \"points_per_second\": %.0f,\n \"point_normal_per_second\": %.0f,\n", points, normals);
  std::printf(" \"second_derivatives_per_second\": %.0f,\n \"checksum\": %.6g}\n", second, sink);
  return 0;
}

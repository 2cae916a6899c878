// Section 2.2, transparency: the three rectangle sets, their colours, their
// order for alpha blending.
#include "stack.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>

#include "../errors.h"
#include "mesh_build.h"

namespace isoform::visualize {
namespace {

void check_settings(const Domain& domain, const StackSettings& s) {
  for (int a = 0; a < 3; ++a)
    if (s.n[a] < 1 || s.n[a] > 1024)
      throw InvalidArgument(domain.what + ": stack grid n = " + std::to_string(s.n[a]) + " along " +
                            "xyz"[a] + "; n must be in 1..1024");
  if (!(s.transparency >= 0.0 && s.transparency <= 1.0))
    throw InvalidArgument(domain.what + ": transparency t = " + std::to_string(s.transparency) +
                          " outside [0, 1]");
  const double len = std::sqrt(s.view[0] * s.view[0] + s.view[1] * s.view[1] + s.view[2] * s.view[2]);
  if (!(len > 0.0) || !std::isfinite(len))
    throw InvalidArgument(domain.what + ": the view direction must be a non-zero vector");
}

// One rectangle: its four grid points (index triples) in cyclic order.
struct Rectangle {
  std::array<std::array<int, 3>, 4> corners;
  double key = 0.0;
};

// The rectangles normal to `axis`: n_u n_v (n_axis + 1) of them.
void add_set(int axis, const std::array<int, 3>& n, std::vector<Rectangle>& out) {
  const int u = axis == 0 ? 1 : 0, v = axis == 2 ? 1 : 2;
  for (int k = 0; k <= n[axis]; ++k)
    for (int j = 0; j < n[v]; ++j)
      for (int i = 0; i < n[u]; ++i) {
        Rectangle r;
        const int du[4] = {0, 1, 1, 0}, dv[4] = {0, 0, 1, 1};
        for (int c = 0; c < 4; ++c) {
          r.corners[c][axis] = k;
          r.corners[c][u] = i + du[c];
          r.corners[c][v] = j + dv[c];
        }
        out.push_back(r);
      }
}

}  // namespace

double depth(const Vec3d& p, const Vec3d& view) {
  return p[0] * view[0] + p[1] * view[1] + p[2] * view[2];
}

Mesh transparency_stack(const ScalarGrid& grid, const Domain& domain, const StackSettings& s,
                        const ColourSettings& colours) {
  check_settings(domain, s);
  // The evaluation grid: (n+1)^3 points across the domain, world and value.
  const int nx = s.n[0] + 1, ny = s.n[1] + 1, nz = s.n[2] + 1;
  const SampleRegion region(grid, domain.lo, domain.hi);
  std::vector<Vec3d> world(size_t(nx) * ny * nz);
  std::vector<double> values(world.size());
  auto at = [&](const std::array<int, 3>& g) { return (size_t(g[2]) * ny + g[1]) * nx + g[0]; };
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        Vec3d p;
        const int g[3] = {i, j, k};
        for (int a = 0; a < 3; ++a)
          p[a] = double(domain.lo[a]) + double(domain.hi[a] - domain.lo[a]) * double(g[a]) / double(s.n[a]);
        world[at({i, j, k})] = domain.world(p);
        values[at({i, j, k})] = region.trilinear(p);
      }
  const ColourScale scale = make_scale(colours, values);
  // The three sets, each rectangle keyed by its corner closest to the screen.
  std::vector<Rectangle> rects;
  for (int axis : {2, 1, 0}) add_set(axis, s.n, rects);  // xy, xz, yz
  for (Rectangle& r : rects) {
    r.key = HUGE_VAL;
    for (const auto& c : r.corners) r.key = std::min(r.key, depth(world[at(c)], s.view));
  }
  std::stable_sort(rects.begin(), rects.end(), [](const Rectangle& a, const Rectangle& b) { return a.key > b.key; });
  const uint8_t alpha = uint8_t(std::lround(255.0 * (1.0 - s.transparency)));
  Mesh mesh;
  for (const Rectangle& r : rects) {
    const int32_t first = int32_t(mesh.vertex_count());
    for (const auto& c : r.corners) {
      const Rgb col = scale.colour(values[at(c)]);
      add_vertex(mesh, world[at(c)], {col[0], col[1], col[2], alpha});
    }
    // Wind each rectangle toward the eye (its normal against view).
    const Vec3d& p0 = world[at(r.corners[0])];
    const Vec3d& p1 = world[at(r.corners[1])];
    const Vec3d& p2 = world[at(r.corners[2])];
    const Vec3d e1{p1[0] - p0[0], p1[1] - p0[1], p1[2] - p0[2]}, e2{p2[0] - p0[0], p2[1] - p0[1], p2[2] - p0[2]};
    const Vec3d n{e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]};
    const bool toward = depth(n, s.view) <= 0;
    if (toward)
      mesh.triangles.insert(mesh.triangles.end(), {first, first + 1, first + 2, first, first + 2, first + 3});
    else
      mesh.triangles.insert(mesh.triangles.end(), {first, first + 2, first + 1, first, first + 3, first + 2});
  }
  compute_vertex_normals(mesh, {-s.view[0], -s.view[1], -s.view[2]});
  return mesh;
}

}  // namespace isoform::visualize

// A slice as a mesh: the coloured plane, or the graph of the slice function
// over it as a shaded surface or a curve network (Section 2.3, Figure 2.9).
#include <algorithm>
#include <cmath>

#include "mesh_build.h"
#include "slices.h"

namespace isoform::visualize {
namespace {

Vec3d unit(const Vec3d& v) {
  const double n = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  return n > 0 ? Vec3d{v[0] / n, v[1] / n, v[2] / n} : Vec3d{0, 0, 1};
}

double largest_extent(const Domain& d) {
  const Vec3d lo = d.world_min(), hi = d.world_max();
  return std::max({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]});
}

}  // namespace

Mesh slice_mesh(const Slice& slice, const Domain& domain, const ColourScale& scale,
                SliceKind kind, double height) {
  Vec3d axis{0, 0, 0};
  axis[slice.axis] = 1.0;
  const Vec3d normal = unit(domain.to_world.apply_normal(axis));
  const double span = scale.f_max - scale.f_min;
  const double lift = kind == SliceKind::Plane ? 0.0 : height * largest_extent(domain);
  Mesh mesh;
  for (int iv = 0; iv < slice.nv; ++iv)
    for (int iu = 0; iu < slice.nu; ++iu) {
      const double f = slice.value(iu, iv);
      const double up = span > 0 ? lift * (std::clamp(f, scale.f_min, scale.f_max) - scale.f_min) / span : 0.0;
      Vec3d p = domain.world(slice.point(iu, iv));
      for (int a = 0; a < 3; ++a) p[a] += up * normal[a];
      const Rgb c = scale.colour(f);
      add_vertex(mesh, p, {c[0], c[1], c[2], 255});
    }
  if (kind == SliceKind::Curves) {
    add_grid_edges(mesh, 0, slice.nu, slice.nv);
    return mesh;
  }
  // (u, v) counter-clockwise faces u x v; keep the triangles facing along
  // the plane's normal when the transform or the axis order turns them.
  Vec3d u{0, 0, 0}, v{0, 0, 0};
  u[slice.u_axis] = 1.0;
  v[slice.v_axis] = 1.0;
  const Vec3d wu = domain.to_world.apply_linear(u), wv = domain.to_world.apply_linear(v);
  const Vec3d cross{wu[1] * wv[2] - wu[2] * wv[1], wu[2] * wv[0] - wu[0] * wv[2], wu[0] * wv[1] - wu[1] * wv[0]};
  const bool flip = cross[0] * normal[0] + cross[1] * normal[1] + cross[2] * normal[2] < 0;
  add_grid_triangles(mesh, 0, slice.nu, slice.nv, flip);
  compute_vertex_normals(mesh, normal);
  return mesh;
}

Mesh domain_outline(const Domain& domain) {
  Mesh mesh;
  for (int c = 0; c < 8; ++c) {
    const Vec3d p{double((c & 1) ? domain.hi[0] : domain.lo[0]), double((c & 2) ? domain.hi[1] : domain.lo[1]),
                  double((c & 4) ? domain.hi[2] : domain.lo[2])};
    add_vertex(mesh, domain.world(p), {0, 0, 0, 255});
  }
  // Corners differing in one bit are joined.
  for (int c = 0; c < 8; ++c)
    for (int bit = 1; bit < 8; bit <<= 1)
      if (!(c & bit)) mesh.edges.insert(mesh.edges.end(), {c, c | bit});
  // Loose vertices need no normal, but the planes they join have them.
  mesh.normals.assign(mesh.points.size(), 0.0f);
  for (size_t v = 0; v < 8; ++v) mesh.normals[3 * v + 2] = 1.0f;
  return mesh;
}

}  // namespace isoform::visualize

// Section 2.3: the three planes, their grids and their samples.
#include "slices.h"

#include <algorithm>
#include <cmath>

#include "../errors.h"

namespace isoform::visualize {
namespace {

constexpr int kUAxis[3] = {1, 0, 0};
constexpr int kVAxis[3] = {2, 2, 1};

// World length of the domain along index axis a.
double world_extent(const Domain& d, int a) {
  Vec3d e{0, 0, 0};
  e[a] = double(d.hi[a] - d.lo[a]);
  const Vec3d w = d.to_world.apply_linear(e);
  return std::sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
}

// Samples along u and v: resolution on the longer side, the other in
// proportion; one sample where the domain is flat.
void grid_size(const Domain& d, int u, int v, int resolution, int& nu, int& nv) {
  const double eu = world_extent(d, u), ev = world_extent(d, v);
  const double longest = std::max(eu, ev);
  auto count = [&](double e, int a) {
    if (d.hi[a] == d.lo[a]) return 1;
    return std::max(2, int(std::lround(double(resolution) * e / longest)));
  };
  nu = count(eu, u);
  nv = count(ev, v);
}

// The index positions c1, c2, c3 of the planes.
Vec3d plane_positions(const Domain& d, const SliceSettings& s) {
  Vec3d c;
  if (s.world) {
    c = d.index(s.position);
  } else {
    for (int a = 0; a < 3; ++a) {
      if (!(s.position[a] >= 0.0 && s.position[a] <= 1.0))
        throw InvalidArgument(d.what + ": slice position " + std::to_string(s.position[a]) +
                              " along " + "xyz"[a] + " is outside the domain (normalised 0..1)");
      c[a] = double(d.lo[a]) + s.position[a] * double(d.hi[a] - d.lo[a]);
    }
  }
  d.require_inside(c, "the slice position");
  return c;
}

Slice sample_one(const ScalarGrid& grid, const Domain& d, int axis, double c, int resolution) {
  Slice s;
  s.axis = axis;
  s.u_axis = kUAxis[axis];
  s.v_axis = kVAxis[axis];
  s.c = c;
  s.lo = d.lo;
  s.hi = d.hi;
  grid_size(d, s.u_axis, s.v_axis, resolution, s.nu, s.nv);
  // Only the slab of samples around the plane is read.
  Index3 lo = d.lo, hi = d.hi;
  lo[axis] = std::clamp(int(std::floor(c)), d.lo[axis], d.hi[axis]);
  hi[axis] = std::min(lo[axis] + 1, d.hi[axis]);
  const SampleRegion region(grid, lo, hi);
  s.values.resize(size_t(s.nu) * size_t(s.nv));
  for (int iv = 0; iv < s.nv; ++iv)
    for (int iu = 0; iu < s.nu; ++iu) s.values[size_t(iv) * size_t(s.nu) + size_t(iu)] = region.trilinear(s.point(iu, iv));
  return s;
}

}  // namespace

Vec3d Slice::point(int iu, int iv) const {
  Vec3d p{0, 0, 0};
  p[axis] = c;
  p[u_axis] = nu > 1 ? lo[u_axis] + double(iu) * double(hi[u_axis] - lo[u_axis]) / double(nu - 1)
                     : double(lo[u_axis]);
  p[v_axis] = nv > 1 ? lo[v_axis] + double(iv) * double(hi[v_axis] - lo[v_axis]) / double(nv - 1)
                     : double(lo[v_axis]);
  return p;
}

std::array<Slice, 3> sample_slices(const ScalarGrid& grid, const Domain& domain,
                                   const SliceSettings& settings) {
  if (settings.resolution < 2 || settings.resolution > 16384)
    throw InvalidArgument(domain.what + ": slice resolution " + std::to_string(settings.resolution) +
                          " outside 2..16384");
  const Vec3d c = plane_positions(domain, settings);
  std::array<Slice, 3> out;
  for (int axis = 0; axis < 3; ++axis) out[axis] = sample_one(grid, domain, axis, c[axis], settings.resolution);
  return out;
}

ColourScale slices_scale(const std::array<Slice, 3>& slices, const ColourSettings& colours) {
  std::vector<double> all;
  for (const Slice& s : slices) all.insert(all.end(), s.values.begin(), s.values.end());
  return make_scale(colours, all);
}

}  // namespace isoform::visualize

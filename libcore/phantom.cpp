// A 3-D head phantom in the manner of Shepp and Logan: nested ellipsoids
// whose densities add up. The table follows the usual 3-D extension of the
// modified Shepp-Logan phantom (skull, brain, ventricles, small lesions).
#include "phantom.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

#include "errors.h"

namespace isoform {
namespace {

struct Ellipsoid {
  double centre[3];
  double axes[3];
  double angle_deg;  // rotation about z
  double density;    // added inside
};

// Outer skull, brain (the skull shell is what remains of density 1), two
// ventricles, lesions. The brain is a little smaller than in the usual table
// and centred, so that the skull is 0.07 thick everywhere: 4.4 voxels at
// 128^3, room for the density ramps of both its surfaces (below).
const Ellipsoid kHead[] = {
    {{0.0, 0.0, 0.0}, {0.69, 0.92, 0.81}, 0, 1.0},
    {{0.0, 0.0, 0.0}, {0.62, 0.85, 0.74}, 0, -0.8},
    {{0.22, 0.0, 0.0}, {0.11, 0.31, 0.22}, -18, -0.2},
    {{-0.22, 0.0, 0.0}, {0.16, 0.41, 0.28}, 18, -0.2},
    {{0.0, 0.35, -0.15}, {0.21, 0.25, 0.41}, 0, 0.1},
    {{0.0, 0.1, 0.25}, {0.046, 0.046, 0.05}, 0, 0.1},
    {{0.0, -0.1, 0.25}, {0.046, 0.046, 0.05}, 0, 0.1},
    {{-0.08, -0.605, 0.0}, {0.046, 0.023, 0.05}, 0, 0.1},
    {{0.0, -0.606, 0.0}, {0.023, 0.023, 0.02}, 0, 0.1},
    {{0.06, -0.605, 0.0}, {0.023, 0.046, 0.02}, 0, 0.1},
};

constexpr double kSkullThickness = 0.07;

// The density ramp across a boundary, d ramp units inside it (a unit is a
// voxel, see ramp_unit): linear within one unit of the boundary (0.5 + d/3),
// where every cell edge that crosses the boundary has its ends, so the
// contour's linear crossings land on the ellipsoid itself; then bending
// smoothly (C1) to 1 or 0 at two units. A ramp clamped within the crossing
// edges' reach would put the crossings on a staircase, and the curvature
// would show the voxel grid, not the head.
double ramp(double d) {
  if (d <= -2.0) return 0.0;
  if (d >= 2.0) return 1.0;
  if (d < -1.0) return (2.0 + d) * (2.0 + d) / 6.0;
  if (d > 1.0) return 1.0 - (2.0 - d) * (2.0 - d) / 6.0;
  return 0.5 + d / 3.0;
}

// A voxel; on grids coarser than about 115^3 a quarter of the skull's
// thickness instead, so that the ramps of its two surfaces do not meet and
// the skull stays (its contour is then a coarse staircase).
double ramp_unit(double voxel) { return std::min(voxel, kSkullThickness / 4); }

// 0 outside the ellipsoid, 1 inside, ramping over two units each side.
double inside(const Ellipsoid& e, double x, double y, double z, double unit) {
  const double c = std::cos(e.angle_deg * M_PI / 180.0), s = std::sin(e.angle_deg * M_PI / 180.0);
  const double dx = x - e.centre[0], dy = y - e.centre[1], dz = z - e.centre[2];
  const double u = (c * dx + s * dy) / e.axes[0], v = (-s * dx + c * dy) / e.axes[1], w = dz / e.axes[2];
  const double r = std::sqrt(u * u + v * v + w * w);
  const double smallest_axis = std::min(e.axes[0], std::min(e.axes[1], e.axes[2]));
  // Signed distance to the boundary, approximately (exact along the
  // smallest axis, less elsewhere), in ramp units.
  return ramp((1.0 - r) * smallest_axis / unit);
}

}  // namespace

std::shared_ptr<VolumeFile> make_phantom(int n) {
  if (n < 16 || n > 1024)
    throw InvalidArgument("phantom size " + std::to_string(n) + " is outside 16..1024 samples per axis");
  const double voxel = 2.0 / (n - 1);
  std::vector<float> values(size_t(n) * size_t(n) * size_t(n));
  tbb::parallel_for(0, n, [&](int k) {
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const double x = -1 + i * voxel, y = -1 + j * voxel, z = -1 + k * voxel;
        double f = 0;
        for (const Ellipsoid& e : kHead) f += e.density * inside(e, x, y, z, ramp_unit(voxel));
        values[(size_t(k) * size_t(n) + size_t(j)) * size_t(n) + size_t(i)] = float(std::clamp(f, 0.0, 1.0));
      }
  });
  const Affine xf = Affine::scale_translate({voxel, voxel, voxel}, {-1, -1, -1});
  return std::make_shared<DenseVolume>("density", GridClass::Fog, std::move(values), Index3{n, n, n}, xf);
}

}  // namespace isoform

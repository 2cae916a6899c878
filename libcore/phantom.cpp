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
// ventricles, lesions.
const Ellipsoid kHead[] = {
    {{0.0, 0.0, 0.0}, {0.69, 0.92, 0.81}, 0, 1.0},
    {{0.0, -0.0184, 0.0}, {0.6624, 0.874, 0.78}, 0, -0.8},
    {{0.22, 0.0, 0.0}, {0.11, 0.31, 0.22}, -18, -0.2},
    {{-0.22, 0.0, 0.0}, {0.16, 0.41, 0.28}, 18, -0.2},
    {{0.0, 0.35, -0.15}, {0.21, 0.25, 0.41}, 0, 0.1},
    {{0.0, 0.1, 0.25}, {0.046, 0.046, 0.05}, 0, 0.1},
    {{0.0, -0.1, 0.25}, {0.046, 0.046, 0.05}, 0, 0.1},
    {{-0.08, -0.605, 0.0}, {0.046, 0.023, 0.05}, 0, 0.1},
    {{0.0, -0.606, 0.0}, {0.023, 0.023, 0.02}, 0, 0.1},
    {{0.06, -0.605, 0.0}, {0.023, 0.046, 0.02}, 0, 0.1},
};

// 1 inside, 0 outside, blending over about one voxel across the boundary.
double inside(const Ellipsoid& e, double x, double y, double z, double voxel) {
  const double c = std::cos(e.angle_deg * M_PI / 180.0), s = std::sin(e.angle_deg * M_PI / 180.0);
  const double dx = x - e.centre[0], dy = y - e.centre[1], dz = z - e.centre[2];
  const double u = (c * dx + s * dy) / e.axes[0], v = (-s * dx + c * dy) / e.axes[1], w = dz / e.axes[2];
  const double r = std::sqrt(u * u + v * v + w * w);
  const double smallest_axis = std::min(e.axes[0], std::min(e.axes[1], e.axes[2]));
  // Signed distance to the boundary, approximately, in voxels.
  const double d = (1.0 - r) * smallest_axis / voxel;
  return std::clamp(0.5 + d, 0.0, 1.0);
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
        for (const Ellipsoid& e : kHead) f += e.density * inside(e, x, y, z, voxel);
        values[(size_t(k) * size_t(n) + size_t(j)) * size_t(n) + size_t(i)] = float(std::clamp(f, 0.0, 1.0));
      }
  });
  const Affine xf = Affine::scale_translate({voxel, voxel, voxel}, {-1, -1, -1});
  return std::make_shared<DenseVolume>("density", GridClass::Fog, std::move(values), Index3{n, n, n}, xf);
}

}  // namespace isoform

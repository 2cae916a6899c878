// Differential geometry of one evaluated sample, and the small vector
// helpers the metrics share.
#pragma once

#include <array>

#include "libcore/surface.h"

namespace isoform::compare {

using V3 = std::array<double, 3>;

inline double dot(const V3& a, const V3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline V3 cross(const V3& a, const V3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
double norm(const V3& a);
double distance(const V3& a, const V3& b);
// The angle between two unit vectors in radians, accurate near 0 (atan2 of
// sine and cosine; acos(1 - 1e-16) would already give 1.5e-8).
double angle_between(const V3& a, const V3& b);

struct SampleCurvature {
  double mean = 0.0, gauss = 0.0;
  bool ok = false;  // false without second derivatives or a regular (u, v)
};

// H and K from the first and second fundamental forms. Sign as in the rest
// of isoform: positive where the surface bends away from its normal (a
// sphere with outward normals has H = 1/r).
SampleCurvature curvature_of(const SurfaceSample& s);

}  // namespace isoform::compare

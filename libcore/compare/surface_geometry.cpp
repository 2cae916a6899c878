#include "surface_geometry.h"

#include <cmath>

namespace isoform::compare {

double norm(const V3& a) { return std::sqrt(dot(a, a)); }

double distance(const V3& a, const V3& b) { return norm({a[0] - b[0], a[1] - b[1], a[2] - b[2]}); }

double angle_between(const V3& a, const V3& b) { return std::atan2(norm(cross(a, b)), dot(a, b)); }

SampleCurvature curvature_of(const SurfaceSample& s) {
  SampleCurvature c;
  if (!s.has_second) return c;
  const double E = dot(s.du, s.du), F = dot(s.du, s.dv), G = dot(s.dv, s.dv);
  const double L = dot(s.duu, s.normal), M = dot(s.duv, s.normal), N = dot(s.dvv, s.normal);
  const double det = E * G - F * F;
  if (!(det > 0.0) || !std::isfinite(det)) return c;
  // The second fundamental form with n gives H < 0 for a sphere with outward
  // n; isoform's sign is the opposite.
  c.mean = -(E * N - 2.0 * F * M + G * L) / (2.0 * det);
  c.gauss = (L * N - M * M) / det;
  c.ok = std::isfinite(c.mean) && std::isfinite(c.gauss);
  return c;
}

}  // namespace isoform::compare

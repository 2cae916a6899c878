// The references of the comparison study. The volume's distance estimate is
// the first-order one, |f - iso| / |grad f|, of the same trilinear
// interpolant the contour follows, taken in index space so it reads in voxels.
#include "reference.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "libcore/errors.h"
#include "libcore/visualize/domain.h"

namespace isoform::compare {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

std::string vec_text(const Vec3d& v) {
  std::ostringstream s;
  s << "(" << v[0] << ", " << v[1] << ", " << v[2] << ")";
  return s.str();
}

class SphereReference : public Reference {
 public:
  SphereReference(const Vec3d& c, double r) : c_(c), r_(r) {}
  double deviation(const Vec3d& p) const override {
    return std::abs(std::hypot(p[0] - c_[0], p[1] - c_[1], p[2] - c_[2]) - r_);
  }
  double mean_curvature(const Vec3d&) const override { return 1.0 / r_; }
  std::string unit() const override { return "world units"; }
  std::string description() const override {
    std::ostringstream s;
    s << "sphere, centre " << vec_text(c_) << ", radius " << r_;
    return s.str();
  }
  std::string kind() const override { return "sphere"; }

 private:
  Vec3d c_;
  double r_;
};

class TorusReference : public Reference {
 public:
  TorusReference(const Vec3d& c, double R, double r) : c_(c), R_(R), r_(r) {}
  double deviation(const Vec3d& p) const override {
    const double rho = std::hypot(p[0] - c_[0], p[1] - c_[1]);
    return std::abs(std::hypot(rho - R_, p[2] - c_[2]) - r_);
  }
  // Tube curvature 1/r and the other principal curvature cos(phi) / (R + r
  // cos(phi)), phi the angle around the tube measured from the outer equator.
  double mean_curvature(const Vec3d& p) const override {
    const double rho = std::hypot(p[0] - c_[0], p[1] - c_[1]);
    const double d = std::hypot(rho - R_, p[2] - c_[2]);
    if (!(d > 0.0)) return kNaN;
    const double cos_phi = (rho - R_) / d;
    return 0.5 * (1.0 / r_ + cos_phi / (R_ + r_ * cos_phi));
  }
  std::string unit() const override { return "world units"; }
  std::string description() const override {
    std::ostringstream s;
    s << "torus around z, centre " << vec_text(c_) << ", radii " << R_ << " and " << r_;
    return s.str();
  }
  std::string kind() const override { return "torus"; }

 private:
  Vec3d c_;
  double R_, r_;
};

class VolumeReference : public Reference {
 public:
  VolumeReference(const ScalarGrid& grid, double iso, const Index3& lo, const Index3& hi, std::string what)
      : region_(grid, lo, hi), lo_(lo), hi_(hi), iso_(iso), what_(std::move(what)) {
    domain_.lo = lo;
    domain_.hi = hi;
    domain_.to_world = grid.index_to_world;
  }
  double deviation(const Vec3d& p) const override {
    const Vec3d x = domain_.index(p);
    int c[3];
    double t[3];
    for (int a = 0; a < 3; ++a) {
      const double q = std::clamp(x[a], double(lo_[a]), double(hi_[a]));
      c[a] = std::min(int(std::floor(q)), hi_[a] - 1);
      t[a] = q - c[a];
    }
    double g[8];
    for (int k = 0; k < 8; ++k) g[k] = region_.at(c[0] + (k & 1), c[1] + (k >> 1 & 1), c[2] + (k >> 2 & 1));
    const double f = trilinear(g, t[0], t[1], t[2]);
    const Vec3d grad = gradient(g, t[0], t[1], t[2]);
    const double len = std::hypot(grad[0], grad[1], grad[2]);
    // Where the interpolant is flat (a cell of equal values) the distance is
    // undefined: NaN, which the measures leave out.
    return len > 0.0 ? std::abs(f - iso_) / len : kNaN;
  }
  double mean_curvature(const Vec3d&) const override { return kNaN; }
  std::string unit() const override { return "voxels"; }
  std::string description() const override {
    std::ostringstream s;
    s << what_ << " at isovalue " << iso_;
    return s.str();
  }
  std::string kind() const override { return "volume"; }

 private:
  static double lerp(double a, double b, double t) { return a + t * (b - a); }
  static double trilinear(const double g[8], double u, double v, double w) {
    return lerp(lerp(lerp(g[0], g[1], u), lerp(g[2], g[3], u), v), lerp(lerp(g[4], g[5], u), lerp(g[6], g[7], u), v), w);
  }
  static Vec3d gradient(const double g[8], double u, double v, double w) {
    const double gx = lerp(lerp(g[1] - g[0], g[3] - g[2], v), lerp(g[5] - g[4], g[7] - g[6], v), w);
    const double gy = lerp(lerp(g[2] - g[0], g[3] - g[1], u), lerp(g[6] - g[4], g[7] - g[5], u), w);
    const double gz = lerp(lerp(g[4] - g[0], g[5] - g[1], u), lerp(g[6] - g[2], g[7] - g[3], u), v);
    return {gx, gy, gz};
  }

  visualize::SampleRegion region_;
  visualize::Domain domain_;
  Index3 lo_, hi_;
  double iso_;
  std::string what_;
};

Vec3d point(const Mesh& mesh, size_t v);

// The area-weighted centroid of the triangles: the centre of a symmetric
// surface however unevenly its vertices are spread (a reduced mesh keeps
// more of them where its curvature estimate was higher; their plain mean
// lies off the centre). The vertices' mean for a mesh without area.
Vec3d centroid(const Mesh& mesh) {
  Vec3d c{0, 0, 0};
  double area = 0.0;
  for (size_t t = 0; t < mesh.triangle_count(); ++t) {
    const Vec3d a = point(mesh, size_t(mesh.triangles[3 * t]));
    const Vec3d b = point(mesh, size_t(mesh.triangles[3 * t + 1]));
    const Vec3d d = point(mesh, size_t(mesh.triangles[3 * t + 2]));
    const Vec3d u{b[0] - a[0], b[1] - a[1], b[2] - a[2]}, w{d[0] - a[0], d[1] - a[1], d[2] - a[2]};
    const double twice = std::hypot(u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2],
                                    u[0] * w[1] - u[1] * w[0]);
    for (int k = 0; k < 3; ++k) c[k] += twice * (a[k] + b[k] + d[k]) / 3.0;
    area += twice;
  }
  if (area > 0.0) {
    for (double& x : c) x /= area;
    return c;
  }
  for (size_t v = 0; v < mesh.vertex_count(); ++v)
    for (int k = 0; k < 3; ++k) c[k] += mesh.points[3 * v + size_t(k)];
  for (double& x : c) x /= double(std::max<size_t>(1, mesh.vertex_count()));
  return c;
}

Vec3d point(const Mesh& mesh, size_t v) {
  return {mesh.points[3 * v], mesh.points[3 * v + 1], mesh.points[3 * v + 2]};
}

}  // namespace

std::unique_ptr<Reference> make_sphere_reference(const Vec3d& centre, double radius) {
  if (!(radius > 0.0) || !std::isfinite(radius))
    throw InvalidArgument("sphere reference: the radius must be positive, not " + std::to_string(radius));
  return std::make_unique<SphereReference>(centre, radius);
}

std::unique_ptr<Reference> make_torus_reference(const Vec3d& centre, double major, double minor) {
  if (!(minor > 0.0 && major > minor) || !std::isfinite(major))
    throw InvalidArgument("torus reference: the radii must satisfy major > minor > 0, not " +
                          std::to_string(major) + " and " + std::to_string(minor));
  return std::make_unique<TorusReference>(centre, major, minor);
}

std::unique_ptr<Reference> make_volume_reference(const ScalarGrid& grid, double iso, const Mesh& mesh,
                                                 const std::string& what) {
  if (mesh.vertex_count() == 0) throw InvalidArgument(what + ": no vertices to place the reference");
  visualize::Domain d;
  d.to_world = grid.index_to_world;
  Vec3d lo{1e300, 1e300, 1e300}, hi{-1e300, -1e300, -1e300};
  for (size_t v = 0; v < mesh.vertex_count(); ++v) {
    const Vec3d x = d.index(point(mesh, v));
    for (int a = 0; a < 3; ++a) lo[a] = std::min(lo[a], x[a]), hi[a] = std::max(hi[a], x[a]);
  }
  // Three voxels of margin: smooth surfaces leave the base mesh's box a
  // little (Loop shrinks inside it; the side-vertex surface bulges out).
  Index3 ilo, ihi;
  for (int a = 0; a < 3; ++a) {
    if (!(hi[a] - lo[a] < 1e7)) throw InvalidArgument(what + ": the mesh is far outside the grid's index range");
    ilo[a] = int(std::floor(lo[a])) - 3;
    ihi[a] = int(std::ceil(hi[a])) + 3;
  }
  return std::make_unique<VolumeReference>(grid, iso, ilo, ihi, what);
}

void fit_sphere(const Mesh& mesh, Vec3d& centre, double& radius) {
  centre = centroid(mesh);
  double sum = 0.0;
  for (size_t v = 0; v < mesh.vertex_count(); ++v) {
    const Vec3d p = point(mesh, v);
    sum += std::hypot(p[0] - centre[0], p[1] - centre[1], p[2] - centre[2]);
  }
  radius = sum / double(std::max<size_t>(1, mesh.vertex_count()));
}

void fit_torus(const Mesh& mesh, Vec3d& centre, double& major, double& minor) {
  centre = centroid(mesh);
  const double n = double(std::max<size_t>(1, mesh.vertex_count()));
  double sum = 0.0;
  for (size_t v = 0; v < mesh.vertex_count(); ++v) {
    const Vec3d p = point(mesh, v);
    sum += std::hypot(p[0] - centre[0], p[1] - centre[1]);
  }
  major = sum / n;
  sum = 0.0;
  for (size_t v = 0; v < mesh.vertex_count(); ++v) {
    const Vec3d p = point(mesh, v);
    sum += std::hypot(std::hypot(p[0] - centre[0], p[1] - centre[1]) - major, p[2] - centre[2]);
  }
  minor = sum / n;
}

}  // namespace isoform::compare

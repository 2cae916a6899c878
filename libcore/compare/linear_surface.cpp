// The flat base triangles: point (1-u-v) p0 + u p1 + v p2, du = p1 - p0,
// dv = p2 - p0, no second derivatives, the face normal everywhere.
#include "linear_surface.h"

#include <cmath>

namespace isoform::compare {
namespace {

class LinearSurface : public TriangleSurface {
 public:
  explicit LinearSurface(const Mesh& mesh) : mesh_(mesh) {}
  size_t triangle_count() const override { return mesh_.triangle_count(); }

  bool evaluate(size_t t, double u, double v, SurfaceSample& out) const override {
    if (t >= triangle_count() || !(u >= 0.0 && v >= 0.0 && u + v <= 1.0 + 1e-12)) return false;
    std::array<double, 3> p[3];
    for (int i = 0; i < 3; ++i) p[i] = corner(mesh_.triangles[3 * t + size_t(i)]);
    for (int c = 0; c < 3; ++c) {
      out.point[c] = (1.0 - u - v) * p[0][c] + u * p[1][c] + v * p[2][c];
      out.du[c] = p[1][c] - p[0][c];
      out.dv[c] = p[2][c] - p[0][c];
    }
    out.duu = out.duv = out.dvv = {0.0, 0.0, 0.0};
    out.has_second = true;
    const auto& a = out.du;
    const auto& b = out.dv;
    const std::array<double, 3> n = {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
    const double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    if (!(len > 0.0)) return false;
    out.normal = {n[0] / len, n[1] / len, n[2] / len};
    return true;
  }

 private:
  std::array<double, 3> corner(int32_t v) const {
    const size_t i = 3 * size_t(v);
    if (mesh_.precise_points.size() == mesh_.points.size())
      return {mesh_.precise_points[i], mesh_.precise_points[i + 1], mesh_.precise_points[i + 2]};
    return {double(mesh_.points[i]), double(mesh_.points[i + 1]), double(mesh_.points[i + 2])};
  }

  const Mesh& mesh_;
};

}  // namespace

std::unique_ptr<TriangleSurface> make_linear_surface(const Mesh& mesh) {
  return std::make_unique<LinearSurface>(mesh);
}

}  // namespace isoform::compare

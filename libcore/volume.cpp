// Affine maps and bricks: the small pieces of the Volume that libcore sees.
#include "volume.h"

#include <cmath>

#include "errors.h"

namespace isoform {

Vec3d Affine::apply(const Vec3d& p) const {
  Vec3d r;
  for (int a = 0; a < 3; ++a) r[a] = m[a][0] * p[0] + m[a][1] * p[1] + m[a][2] * p[2] + m[a][3];
  return r;
}

Vec3d Affine::apply_linear(const Vec3d& v) const {
  Vec3d r;
  for (int a = 0; a < 3; ++a) r[a] = m[a][0] * v[0] + m[a][1] * v[1] + m[a][2] * v[2];
  return r;
}

double Affine::determinant() const {
  return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
         m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
         m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
}

void Affine::cofactors(double c[3][3]) const {
  c[0][0] = m[1][1] * m[2][2] - m[1][2] * m[2][1];
  c[0][1] = m[1][2] * m[2][0] - m[1][0] * m[2][2];
  c[0][2] = m[1][0] * m[2][1] - m[1][1] * m[2][0];
  c[1][0] = m[0][2] * m[2][1] - m[0][1] * m[2][2];
  c[1][1] = m[0][0] * m[2][2] - m[0][2] * m[2][0];
  c[1][2] = m[0][1] * m[2][0] - m[0][0] * m[2][1];
  c[2][0] = m[0][1] * m[1][2] - m[0][2] * m[1][1];
  c[2][1] = m[0][2] * m[1][0] - m[0][0] * m[1][2];
  c[2][2] = m[0][0] * m[1][1] - m[0][1] * m[1][0];
}

Vec3d Affine::apply_normal(const Vec3d& n) const {
  // The inverse transpose equals the cofactor matrix divided by the
  // determinant; the division only scales, so the cofactors suffice, and the
  // sign of the determinant keeps the normal on the same side.
  double c[3][3];
  cofactors(c);
  const double s = determinant() < 0 ? -1.0 : 1.0;
  Vec3d r;
  for (int a = 0; a < 3; ++a) r[a] = s * (c[a][0] * n[0] + c[a][1] * n[1] + c[a][2] * n[2]);
  return r;
}

Vec3d Affine::voxel_size() const {
  Vec3d r;
  for (int b = 0; b < 3; ++b) r[b] = std::sqrt(m[0][b] * m[0][b] + m[1][b] * m[1][b] + m[2][b] * m[2][b]);
  return r;
}

Affine Affine::scale_translate(const Vec3d& scale, const Vec3d& translate) {
  Affine a;
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) a.m[r][c] = r == c ? scale[r] : 0.0;
    a.m[r][3] = translate[r];
  }
  return a;
}

void Brick::resize(const Index3& origin_, const Index3& cells_, bool with_defined) {
  origin = origin_;
  cells = cells_;
  const Index3 d = dims();
  const size_t n = size_t(d[0]) * size_t(d[1]) * size_t(d[2]);
  samples.resize(n);
  if (with_defined)
    defined.assign(n, 0);
  else
    defined.clear();
}

void check_finite(const std::vector<float>& values, const std::string& what) {
  for (size_t i = 0; i < values.size(); ++i) {
    if (!std::isfinite(values[i]))
      throw FormatError(what + ": sample " + std::to_string(i) + " is " +
                        (std::isnan(values[i]) ? "NaN" : "infinite") +
                        "; isoform needs finite values");
  }
}

}  // namespace isoform

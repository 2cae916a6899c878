// The replacement point and its curvature (see replacement.h).
#include "replacement.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

#include "../curvature/principal.h"

namespace isoform::reduce {
namespace {

// Platelet vertices in world coordinates: T's three and the polygon's.
void platelet_points(const WorkMesh& w, const Platelet& p, std::vector<Eigen::Vector3d>& out) {
  out.clear();
  for (int v : p.a) out.push_back(w.pos[size_t(v)]);
  for (int v : p.ring) out.push_back(w.pos[size_t(v)]);
}

double platelet_radius(const std::vector<Eigen::Vector3d>& pts, const Eigen::Vector3d& c) {
  double h = 0;
  for (const auto& x : pts) h = std::max(h, (x - c).norm());
  return h;
}

// Least squares by the normal equations (5.28); false when they are too
// badly conditioned (smallest over largest LDLT pivot below 1e-10).
template <int N>
bool solve_normal(const Eigen::Matrix<double, N, N>& ata, const Eigen::Matrix<double, N, 1>& atb,
                  Eigen::Matrix<double, N, 1>& x) {
  Eigen::LDLT<Eigen::Matrix<double, N, N>> ldlt(ata);
  if (ldlt.info() != Eigen::Success) return false;
  const auto d = ldlt.vectorD();
  const double lo = d.cwiseAbs().minCoeff(), hi = d.cwiseAbs().maxCoeff();
  if (!(hi > 0) || lo < 1e-10 * hi) return false;
  x = ldlt.solve(atb);
  return x.allFinite();
}

// c20 c11 c10 c02 c01 c00 in coordinates scaled by 1/h (5.27).
struct Quadratic {
  double c20 = 0, c11 = 0, c10 = 0, c02 = 0, c01 = 0, c00 = 0;
  int terms = 0;
  double value(double u, double v) const { return c20 * u * u + c11 * u * v + c10 * u + c02 * v * v + c01 * v + c00; }
};

Quadratic fit_quadratic(const std::vector<Eigen::Vector3d>& pts, const Frame& f, double h, bool plane_only) {
  Quadratic q;
  Eigen::Matrix<double, 6, 6> ata = Eigen::Matrix<double, 6, 6>::Zero();
  Eigen::Matrix<double, 6, 1> atb = Eigen::Matrix<double, 6, 1>::Zero();
  Eigen::Matrix3d pa = Eigen::Matrix3d::Zero();
  Eigen::Vector3d pb = Eigen::Vector3d::Zero();
  for (const auto& x : pts) {
    const Eigen::Vector3d r = (x - f.c) / h;
    const double u = r.dot(f.b1), v = r.dot(f.b2), d = r.dot(f.n);
    Eigen::Matrix<double, 6, 1> row;
    row << u * u, u * v, u, v * v, v, 1.0;
    ata += row * row.transpose();
    atb += row * d;
    const Eigen::Vector3d lin(u, v, 1.0);
    pa += lin * lin.transpose();
    pb += lin * d;
  }
  Eigen::Matrix<double, 6, 1> c;
  if (!plane_only && pts.size() >= 6 && solve_normal<6>(ata, atb, c)) {
    q = {c(0), c(1), c(2), c(3), c(4), c(5), 6};
    return q;
  }
  // Too few or badly placed points: the plane of the points (3 terms).
  Eigen::Matrix<double, 3, 1> l;
  if (pts.size() >= 3 && solve_normal<3>(pa, pb, l)) {
    q.c10 = l(0);
    q.c01 = l(1);
    q.c00 = l(2);
    q.terms = 3;
  }
  return q;
}

// Is height d (scaled by 1/h, along n) within the platelet's heights
// widened by their span on both sides?
bool height_plausible(const std::vector<Eigen::Vector3d>& pts, const Frame& f, double h, double d) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const auto& x : pts) {
    const double dj = (x - f.c).dot(f.n) / h;
    lo = std::min(lo, dj);
    hi = std::max(hi, dj);
  }
  const double span = hi - lo;
  return std::isfinite(d) && d >= lo - span && d <= hi + span;
}

// The point on the fitted graph X(u, v) = c + h (u b1 + v b2 + q(u, v) n)
// whose (x, y) equals c's: two Newton steps from (0, 0) suffice for the
// small slopes of a boundary corona; more are taken when needed.
Eigen::Vector2d keep_xy_parameter(const Quadratic& q, const Frame& f) {
  Eigen::Vector2d uv(0, 0);
  for (int it = 0; it < 8; ++it) {
    const double u = uv(0), v = uv(1);
    const Eigen::Vector3d x = u * f.b1 + v * f.b2 + q.value(u, v) * f.n;
    const Eigen::Vector3d xu = f.b1 + (2 * q.c20 * u + q.c11 * v + q.c10) * f.n;
    const Eigen::Vector3d xv = f.b2 + (q.c11 * u + 2 * q.c02 * v + q.c01) * f.n;
    Eigen::Matrix2d j;
    j << xu(0), xv(0), xu(1), xv(1);
    if (std::abs(j.determinant()) < 1e-12) break;
    const Eigen::Vector2d step = j.inverse() * Eigen::Vector2d(x(0), x(1));
    uv -= step;
    if (step.norm() < 1e-15) break;
  }
  return uv;
}

Replacement quadratic_point(const std::vector<Eigen::Vector3d>& pts, const Frame& f, double h, bool keep_xy) {
  Replacement r;
  r.ok = true;
  Quadratic q = fit_quadratic(pts, f, h, false);
  Eigen::Vector2d uv = keep_xy ? keep_xy_parameter(q, f) : Eigen::Vector2d(0, 0);
  // NOTE: on irregular platelets of real contours the quadratic can
  // extrapolate wildly at the origin (a point hundreds of edge lengths off
  // was seen on headsq). A height outside the platelet's own range widened by
  // its span is not believed: the plane of the points is used instead.
  if (!height_plausible(pts, f, h, q.value(uv(0), uv(1)))) {
    q = fit_quadratic(pts, f, h, true);
    uv = keep_xy ? keep_xy_parameter(q, f) : Eigen::Vector2d(0, 0);
  }
  r.fit_terms = q.terms;
  const double u = uv(0), v = uv(1);
  r.point = f.c + h * (u * f.b1 + v * f.b2 + q.value(u, v) * f.n);
  // Theorem 5.5 is the curvature of the graph of the quadratic, with the
  // first fundamental form's lower right entry 1 + c01^2 (its proof prints
  // 1 + c01; the derivation and (5.35) itself give the square);
  // principal_curvatures evaluates it from the derivatives.
  HeightFit hf;
  hf.ok = true;
  hf.fu = 2 * q.c20 * u + q.c11 * v + q.c10;
  hf.fv = q.c11 * u + 2 * q.c02 * v + q.c01;
  hf.fuu = 2 * q.c20 / h;
  hf.fuv = q.c11 / h;
  hf.fvv = 2 * q.c02 / h;
  const PrincipalCurvatures pc = principal_curvatures(hf, f.b1, f.b2, f.n);
  r.k1 = pc.k1;
  r.k2 = pc.k2;
  r.d1 = pc.d1;
  r.d2 = pc.d2;
  r.normal = pc.normal;
  return r;
}

// The ten monomials of a quadric in x y z (5.31): xx xy xz yy yz zz x y z 1.
Eigen::Matrix<double, 10, 1> quadric_row(const Eigen::Vector3d& x) {
  Eigen::Matrix<double, 10, 1> r;
  r << x(0) * x(0), x(0) * x(1), x(0) * x(2), x(1) * x(1), x(1) * x(2), x(2) * x(2), x(0), x(1), x(2), 1.0;
  return r;
}

// Fits the quadric in coordinates (x - c) / h, where every platelet point is
// within distance 1 of the origin, with the constraint f(1, 1, 1) = 1 of
// (5.30) taken in those coordinates (the normalisation is arbitrary, Remark
// 5.5; there (1,1,1) is never a data point). With fewer than nine points the
// subset of Remark 5.6 without squares (xy xz yz x y z 1). False: no fit.
bool fit_quadric(const std::vector<Eigen::Vector3d>& pts, const Frame& f, double h,
                 Eigen::Matrix<double, 10, 1>& coef) {
  const int n = int(pts.size());
  Eigen::Matrix<double, 10, 10> ata = Eigen::Matrix<double, 10, 10>::Zero();
  for (const auto& x : pts) {
    const auto row = quadric_row((x - f.c) / h);
    ata += row * row.transpose();
  }
  const auto one = quadric_row(Eigen::Vector3d(1, 1, 1));
  ata += one * one.transpose();
  const Eigen::Matrix<double, 10, 1> atb = one;
  if (n >= 9) return solve_normal<10>(ata, atb, coef);
  if (n < 6) return false;
  // Remark 5.6: keep xy xz yz x y z 1 (indices 1 2 4 6 7 8 9).
  const int keep[7] = {1, 2, 4, 6, 7, 8, 9};
  Eigen::Matrix<double, 7, 7> a7;
  Eigen::Matrix<double, 7, 1> b7, c7;
  for (int i = 0; i < 7; ++i) {
    b7(i) = atb(keep[i]);
    for (int j = 0; j < 7; ++j) a7(i, j) = ata(keep[i], keep[j]);
  }
  if (!solve_normal<7>(a7, b7, c7)) return false;
  coef.setZero();
  for (int i = 0; i < 7; ++i) coef(keep[i]) = c7(i);
  return true;
}

Replacement quadric_point(const std::vector<Eigen::Vector3d>& pts, const Frame& f, double h, bool keep_xy) {
  Eigen::Matrix<double, 10, 1> c;
  if (keep_xy || !fit_quadric(pts, f, h, c)) return quadratic_point(pts, f, h, keep_xy);
  Eigen::Matrix3d Q;
  Q << c(0), c(1) / 2, c(2) / 2, c(1) / 2, c(3), c(4) / 2, c(2) / 2, c(4) / 2, c(5);
  const Eigen::Vector3d g(c(6), c(7), c(8));
  // (5.33) with c at the origin: t^2 n'Qn + t g.n + c0 = 0; the root nearer P.
  const double qa = f.n.dot(Q * f.n), qb = g.dot(f.n), qc = c(9);
  double t = 0;
  if (std::abs(qa) < 1e-14) {
    if (std::abs(qb) > 1e-14) t = -qc / qb;
  } else {
    const double disc = qb * qb - 4 * qa * qc;
    if (disc >= 0) {
      const double s = std::sqrt(disc);
      const double t1 = (-qb + s) / (2 * qa), t2 = (-qb - s) / (2 * qa);
      t = std::abs(t1) < std::abs(t2) ? t1 : t2;
    }
  }
  if (!std::isfinite(t) || std::abs(t) > 1.0 || !height_plausible(pts, f, h, t)) return quadratic_point(pts, f, h, keep_xy);
  Replacement r;
  r.ok = true;
  r.fit_terms = 10;
  r.point = f.c + h * t * f.n;
  // Theorem 5.6 as the shape operator of the implicit surface: with
  // N = grad/|grad| turned to T's side, the curvature along tangent b is
  // b' Hess b / |grad| (positive where the surface bends away from N).
  Eigen::Vector3d grad = 2 * Q * (t * f.n) + g;
  Eigen::Matrix3d hess = 2 * Q;
  if (grad.dot(f.n) < 0) {
    grad = -grad;
    hess = -hess;
  }
  const double gn = grad.norm();
  if (!(gn > 1e-14)) return quadratic_point(pts, f, h, keep_xy);
  r.normal = grad / gn;
  Eigen::Vector3d t1 = f.b1 - f.b1.dot(r.normal) * r.normal;
  t1.normalize();
  const Eigen::Vector3d t2 = r.normal.cross(t1);
  Eigen::Matrix2d s;
  s << t1.dot(hess * t1), t1.dot(hess * t2), t2.dot(hess * t1), t2.dot(hess * t2);
  s /= gn * h;
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> es(s);
  r.k1 = es.eigenvalues()(1);
  r.k2 = es.eigenvalues()(0);
  r.d1 = (es.eigenvectors()(0, 1) * t1 + es.eigenvectors()(1, 1) * t2).normalized();
  r.d2 = r.normal.cross(r.d1);
  return r;
}

}  // namespace

Frame platelet_frame(const WorkMesh& w, const Platelet& p, bool* ok) {
  Frame f;
  const Eigen::Vector3d& a0 = w.pos[size_t(p.a[0])];
  const Eigen::Vector3d d1 = w.pos[size_t(p.a[1])] - a0, d2 = w.pos[size_t(p.a[2])] - a0;
  const Eigen::Vector3d cr = d1.cross(d2);
  *ok = cr.norm() > 1e-300 && d1.norm() > 0;
  f.n = *ok ? Eigen::Vector3d(cr.normalized()) : Eigen::Vector3d(0, 0, 1);
  f.b1 = *ok ? Eigen::Vector3d(d1.normalized()) : Eigen::Vector3d(1, 0, 0);
  f.b2 = f.n.cross(f.b1);
  f.c = p.origin;
  return f;
}

Replacement replacement_point(const WorkMesh& w, const Platelet& p, const Frame& frame, ReducePoint method,
                              bool keep_xy) {
  static thread_local std::vector<Eigen::Vector3d> pts;
  platelet_points(w, p, pts);
  const double h = platelet_radius(pts, frame.c);
  if (!(h > 0)) return {};
  return method == ReducePoint::Quadric ? quadric_point(pts, frame, h, keep_xy)
                                        : quadratic_point(pts, frame, h, keep_xy);
}

}  // namespace isoform::reduce

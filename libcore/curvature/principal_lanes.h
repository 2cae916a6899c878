// principal_curvatures_inline (principal.h) for four fits at once, one per
// lane: the same operations in the same order, so each lane has the bits
// the one-fit form gives (vectors as Eigen evaluates them: a squared norm
// is (x^2 + y^2) + z^2, a normalisation divides by its square root and
// leaves a zero vector as it is).
#pragma once

#include "lanes4.h"
#include "principal.h"

namespace isoform {

struct HeightFitLanes {
  Lanes4 fu, fv, fuu, fuv, fvv;
};

struct PrincipalLanes {
  Lanes4 k1, k2;
  Vec3Lanes d1, d2, normal;
};

namespace lanes_detail {

ISOFORM_LANES_INLINE Vec3Lanes normalized(const Vec3Lanes& t) {
  const Lanes4 z = (t.x * t.x + t.y * t.y) + t.z * t.z;
  const Lanes4 inv = splat4(1.0) / sqrt4(z);
  const Mask4 positive = z > splat4(0.0);
  return {select4(positive, t.x * inv, t.x), select4(positive, t.y * inv, t.y), select4(positive, t.z * inv, t.z)};
}

ISOFORM_LANES_INLINE Vec3Lanes cross(const Vec3Lanes& a, const Vec3Lanes& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

}  // namespace lanes_detail

ISOFORM_LANES_INLINE PrincipalLanes principal_curvatures_lanes(const HeightFitLanes& f, const Vec3Lanes& b1,
                                                               const Vec3Lanes& b2, const Vec3Lanes& n) {
  using lanes_detail::cross;
  using lanes_detail::normalized;
  PrincipalLanes pc;
  const Lanes4 one = splat4(1.0), zero = splat4(0.0);
  const Lanes4 l = sqrt4((one + f.fu * f.fu) + f.fv * f.fv);
  const Lanes4 E = one + f.fu * f.fu, F = f.fu * f.fv, G = one + f.fv * f.fv;
  const Lanes4 inv_l = one / l;
  const Lanes4 L = -f.fuu * inv_l, M = -f.fuv * inv_l, N = -f.fvv * inv_l;
  const Lanes4 det_i = E * G - F * F;
  const Lanes4 inv_det = one / det_i;
  const Lanes4 w11 = (G * L - F * M) * inv_det, w12 = (G * M - F * N) * inv_det;
  const Lanes4 w21 = (E * M - F * L) * inv_det, w22 = (E * N - F * M) * inv_det;
  const Lanes4 h = splat4(0.5) * (w11 + w22), k = w11 * w22 - w12 * w21;
  const Lanes4 disc = sqrt4(max4(zero, h * h - k));
  pc.k1 = h + disc;
  pc.k2 = h - disc;
  const Vec3Lanes xu = {b1.x + f.fu * n.x, b1.y + f.fu * n.y, b1.z + f.fu * n.z};
  const Vec3Lanes xv = {b2.x + f.fv * n.x, b2.y + f.fv * n.y, b2.z + f.fv * n.z};
  pc.normal = {((n.x - f.fu * b1.x) - f.fv * b2.x) * inv_l, ((n.y - f.fu * b1.y) - f.fv * b2.y) * inv_l,
               ((n.z - f.fu * b1.z) - f.fv * b2.z) * inv_l};
  const Lanes4 a1 = w11 - pc.k1, a2 = w22 - pc.k1;
  const Lanes4 r1 = a1 * a1 + w12 * w12, r2 = w21 * w21 + a2 * a2;
  const Lanes4 tiny = splat4(1e-12) * ((abs4(pc.k1) + abs4(pc.k2)) + splat4(1e-300));
  // e = (1, 0) at an umbilic, else from the larger row of (W - k1 I).
  const Mask4 umbilic = max4(r1, r2) <= tiny * tiny, first_row = r1 >= r2;
  const Lanes4 e0 = select4(umbilic, one, select4(first_row, w12, pc.k1 - w22));
  const Lanes4 e1 = select4(umbilic, zero, select4(first_row, pc.k1 - w11, w21));
  pc.d1 = normalized({e0 * xu.x + e1 * xv.x, e0 * xu.y + e1 * xv.y, e0 * xu.z + e1 * xv.z});
  pc.d2 = normalized(cross(pc.normal, pc.d1));
  return pc;
}

// The frame of four vertices from their unit normals, as Eigen's
// unitOrthogonal and cross give it: b1 = (-y, x, 0) / |(x, y)| unless x and
// y are both much smaller than z (|.| <= 1e-12 |z|), then (0, -z, y) /
// |(y, z)|; b2 = n x b1.
ISOFORM_LANES_INLINE void frame_lanes(const Vec3Lanes& n, Vec3Lanes& b1, Vec3Lanes& b2) {
  const Lanes4 zero = splat4(0.0), one = splat4(1.0), limit = abs4(n.z) * splat4(1e-12);
  const Mask4 near_z = (abs4(n.x) <= limit) & (abs4(n.y) <= limit);
  const Lanes4 inv_xy = one / sqrt4(n.x * n.x + n.y * n.y), inv_yz = one / sqrt4(n.y * n.y + n.z * n.z);
  b1.x = select4(near_z, zero, -n.y * inv_xy);
  b1.y = select4(near_z, -n.z * inv_yz, n.x * inv_xy);
  b1.z = select4(near_z, n.y * inv_yz, zero);
  b2 = lanes_detail::cross(n, b1);
}

// Four Eigen vectors, one per lane.
ISOFORM_LANES_INLINE Vec3Lanes vec3_lanes(const Eigen::Vector3d (&a)[4]) {
  return {Lanes4{a[0](0), a[1](0), a[2](0), a[3](0)}, Lanes4{a[0](1), a[1](1), a[2](1), a[3](1)},
          Lanes4{a[0](2), a[1](2), a[2](2), a[3](2)}};
}

// Lane l of p as principal_curvatures gives it.
ISOFORM_LANES_INLINE PrincipalCurvatures principal_of_lane(const PrincipalLanes& p, int l) {
  PrincipalCurvatures c;
  c.k1 = p.k1[l];
  c.k2 = p.k2[l];
  c.d1 = {p.d1.x[l], p.d1.y[l], p.d1.z[l]};
  c.d2 = {p.d2.x[l], p.d2.y[l], p.d2.z[l]};
  c.normal = {p.normal.x[l], p.normal.y[l], p.normal.z[l]};
  return c;
}

}  // namespace isoform

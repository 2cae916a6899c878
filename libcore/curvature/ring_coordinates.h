// Local coordinates (4.27) and signed heights (4.24) of a vertex's gathered
// neighbours, in the frame (b1, b2, n) at the vertex: the one loop both the
// general fit (vertex_fit.cpp) and the seed's short path (seed_vertex.cpp)
// run, so the two give the same bits.
#ifndef ISOFORM_CURVATURE_RING_COORDINATES_H
#define ISOFORM_CURVATURE_RING_COORDINATES_H

#include <Eigen/Core>

#include <algorithm>

#include <cstddef>
#include <cstdint>

#include "lanes4.h"

namespace isoform {

// Writes u, v and the height d of every neighbour in [ring, end) into pu, pv,
// pd and returns how many were kept: a neighbour that coincides with the
// vertex (u = v = 0) carries nothing and is left out. Point j goes to entry
// j * Stride (the four-lane fits' layout has Stride 4). Each array needs
// one entry to spare, since a point is written before it is known to stay.
template <int Stride = 1, class Real>
int ring_coordinates(const Real* points, int32_t v, const int32_t* ring, const int32_t* end,
                     const Eigen::Vector3d& b1, const Eigen::Vector3d& b2, const Eigen::Vector3d& n, double* pu,
                     double* pv, double* pd) {
  const Real* q = points + 3 * size_t(v);
  const double ox = q[0], oy = q[1], oz = q[2];
  // The frame in locals: the stores below could alias it, and would make
  // the compiler read it again for every point.
  const double e0 = b1(0), e1 = b1(1), e2 = b1(2), f0 = b2(0), f1 = b2(1), f2 = b2(2);
  const double n0 = n(0), n1 = n(1), n2 = n(2);
  int count = 0;
  for (; ring != end; ++ring) {
    const Real* p = points + 3 * size_t(*ring);
    const double x = double(p[0]) - ox, y = double(p[1]) - oy, z = double(p[2]) - oz;
    const double u = x * e0 + y * e1 + z * e2, vv = x * f0 + y * f1 + z * f2;
    // Written always, kept unless it coincides with the vertex (no branch).
    pu[Stride * count] = u;
    pv[Stride * count] = vv;
    pd[Stride * count] = x * n0 + y * n1 + z * n2;
    count += !(u == 0.0 && vv == 0.0);
  }
  return count;
}

// ring_coordinates for four vertices side by side: vertex[l]'s ring[l]
// (valence[l] points; 0 for an unused lane) in frame (b1, b2, n) lane l,
// point j of lane l into u[4 j + l], v[4 j + l], d[4 j + l], every lane
// padded with zeros up to the largest valence, which is returned. The same
// operations in the same order as ring_coordinates, so the same bits, but
// no point is left out: a lane where a neighbour coincides with its vertex
// is marked in `coincide` (ring_coordinates would leave that point out).
template <class Real>
ISOFORM_LANES_INLINE int ring_coordinates_lanes(const Real* points, const int32_t (&vertex)[4],
                                                const int32_t* const (&ring)[4], const int (&valence)[4],
                                                const Vec3Lanes& b1, const Vec3Lanes& b2, const Vec3Lanes& n,
                                                double* u, double* v, double* d, bool (&coincide)[4]) {
  // Vectors are built whole from scalars in registers (not written lane by
  // lane through memory, which stalls the vector read that follows).
  const Real *q0 = points + 3 * size_t(vertex[0]), *q1 = points + 3 * size_t(vertex[1]),
             *q2 = points + 3 * size_t(vertex[2]), *q3 = points + 3 * size_t(vertex[3]);
  const Lanes4 ox = {double(q0[0]), double(q1[0]), double(q2[0]), double(q3[0])};
  const Lanes4 oy = {double(q0[1]), double(q1[1]), double(q2[1]), double(q3[1])};
  const Lanes4 oz = {double(q0[2]), double(q1[2]), double(q2[2]), double(q3[2])};
  const int most = std::max(std::max(valence[0], valence[1]), std::max(valence[2], valence[3]));
  const int all = std::min(std::min(valence[0], valence[1]), std::min(valence[2], valence[3]));
  const Lanes4 zero = splat4(0.0);
  Mask4 any_same = {0, 0, 0, 0};
  // Point j of every lane from p0 .. p3, kept where `here`.
  auto point = [&](int j, const Real* p0, const Real* p1, const Real* p2, const Real* p3, Mask4 here) {
    const Lanes4 x = Lanes4{double(p0[0]), double(p1[0]), double(p2[0]), double(p3[0])} - ox;
    const Lanes4 y = Lanes4{double(p0[1]), double(p1[1]), double(p2[1]), double(p3[1])} - oy;
    const Lanes4 z = Lanes4{double(p0[2]), double(p1[2]), double(p2[2]), double(p3[2])} - oz;
    const Lanes4 uu = (x * b1.x + y * b1.y) + z * b1.z, vv = (x * b2.x + y * b2.y) + z * b2.z;
    const Lanes4 du = select4(here, uu, zero), dv = select4(here, vv, zero),
                 dd = select4(here, (x * n.x + y * n.y) + z * n.z, zero);
    __builtin_memcpy(u + 4 * size_t(j), &du, sizeof(du));
    __builtin_memcpy(v + 4 * size_t(j), &dv, sizeof(dv));
    __builtin_memcpy(d + 4 * size_t(j), &dd, sizeof(dd));
    any_same |= here & (uu == zero) & (vv == zero);
  };
  // Points every lane has, then the lanes' longer tails.
  const Mask4 every = {-1, -1, -1, -1};
  for (int j = 0; j < all; ++j)
    point(j, points + 3 * size_t(ring[0][j]), points + 3 * size_t(ring[1][j]), points + 3 * size_t(ring[2][j]),
          points + 3 * size_t(ring[3][j]), every);
  for (int j = all; j < most; ++j) {
    const bool h0 = j < valence[0], h1 = j < valence[1], h2 = j < valence[2], h3 = j < valence[3];
    point(j, h0 ? points + 3 * size_t(ring[0][j]) : q0, h1 ? points + 3 * size_t(ring[1][j]) : q1,
          h2 ? points + 3 * size_t(ring[2][j]) : q2, h3 ? points + 3 * size_t(ring[3][j]) : q3,
          Mask4{-int64_t(h0), -int64_t(h1), -int64_t(h2), -int64_t(h3)});
  }
  for (int l = 0; l < 4; ++l) coincide[l] = any_same[l] != 0;
  return most;
}

}  // namespace isoform

#endif

// Local coordinates (4.27) and signed heights (4.24) of a vertex's gathered
// neighbours, in the frame (b1, b2, n) at the vertex: the one loop both the
// general fit (vertex_fit.cpp) and the seed's short path (seed_vertex.cpp)
// run, so the two give the same bits.
#ifndef ISOFORM_CURVATURE_RING_COORDINATES_H
#define ISOFORM_CURVATURE_RING_COORDINATES_H

#include <Eigen/Core>

#include <cstddef>
#include <cstdint>

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

}  // namespace isoform

#endif

// The point of one side-vertex patch at (u, v) (Hamann 1991, Section 6.3),
// as a template over the scalar: double for points, Jet for derivatives.
// Corners (two barycentric coordinates zero) are the caller's: there the
// weights (6.2) are 0/0.
#pragma once

#include "side_vertex_surface.h"

namespace isoform::patch {

// Building block s_i: the conic from vertex i (normal n_i) to the point q of
// the boundary curve on the opposite edge at t = u_k / (u_j + u_k), with the
// boundary normal there, evaluated at 1 - u_i = u_j + u_k.
template <class T>
V3<T> building_block(const SideVertexSurface& s, size_t tri, int i, const T* bary) {
  const int j = (i + 1) % 3, k = (i + 2) % 3;
  const T rest = bary[j] + bary[k];
  const T t_local = bary[k] / rest;  // 0 at vertex j, 1 at vertex k
  const TriangleEdge te = s.triangle_edge(tri, i);
  const T t_curve = te.reversed ? bary[j] / rest : t_local;
  const EdgeValue<T> q = edge_eval(s.edge_curve(size_t(te.edge)), t_curve);
  // The radial curve meets the edges i-j (t = 0) and i-k (t = 1): its
  // tension runs between theirs, so there it is their boundary curve.
  const double inv_ij = s.edge_inv_tension(size_t(s.triangle_edge(tri, k).edge));
  const double inv_ik = s.edge_inv_tension(size_t(s.triangle_edge(tri, j).edge));
  const T inv = (1.0 - t_local) * inv_ij + t_local * inv_ik;
  const int32_t vi = s.triangle_vertex(tri, i);
  const Conic<T> radial =
      make_conic(V3<T>::from(s.vertex(size_t(vi))), V3<T>::from(s.vertex_normal(size_t(vi))), q.point, q.normal, inv);
  return conic_point(radial, rest);
}

// The blend (6.1) of the three building blocks. Returns false where the
// weights' denominator vanishes (a corner) or underflows.
template <class T>
bool patch_point(const SideVertexSurface& s, size_t tri, const T& u, const T& v, V3<T>& out) {
  const T bary[3] = {1.0 - u - v, u, v};
  T weight[3];
  T sum(0.0);
  for (int i = 0; i < 3; ++i) {
    const T w = bary[(i + 1) % 3] * bary[(i + 2) % 3];
    weight[i] = s.options().blend == Blend::Squared ? w * w : w;
    sum = sum + weight[i];
  }
  // NOTE: a normal number keeps 1 / sum finite; below it (within ~1e-77 of
  // a corner for the squared weights) the point is the corner's.
  if (!(value_of(sum) >= 1e-300)) return false;
  V3<T> p(T(0.0), T(0.0), T(0.0));
  for (int i = 0; i < 3; ++i) {
    // NOTE: every block counts, also where its weight is 0: on an edge the
    // derivatives of the weights add up to zero only all together.
    p = p + (weight[i] / sum) * building_block(s, tri, i, bary);
  }
  out = p;
  return true;
}

}  // namespace isoform::patch

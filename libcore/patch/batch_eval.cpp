// Batch evaluation of the side-vertex patch (batch_eval.h): a plan per chunk
// of samples (which go the scalar way, the distinct t of each building
// block), the radial conics of the distinct t four at a time, then the
// patch points four at a time.
#include "batch_eval.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>

#include "batch_lanes.h"
#include "side_vertex_surface.h"

namespace isoform::patch {
namespace {

using lanes::J1;
using lanes::J2;
using lanes::L;
using lanes::M;
using lanes::Radial;
using lanes::V2;

constexpr size_t kChunk = 64;
constexpr size_t kGroups = kChunk / 4;

// What a chunk's lanes work on: the samples that take the lane path, and
// per building block the distinct t and each sample's index into them.
struct Plan {
  size_t n = 0;             // samples of the chunk
  size_t m = 0;             // of them on the lane path
  uint8_t sample[kChunk];  // their positions in the chunk
  double t[3][kChunk];     // distinct t of block i (sorted)
  size_t distinct[3];
  uint8_t index[3][kChunk];  // lane sample -> its t in t[i]
  bool bad_t[3][kChunk];     // the t's conic took a rare branch
  bool scalar[kChunk];       // chunk sample -> scalar path
};

// The blend's weight sum as patch_point computes it (false: a corner).
bool inside(const PatchOptions& o, double u, double v) {
  const double b[3] = {(1.0 - u) - v, u, v};
  double sum = 0.0;
  for (int i = 0; i < 3; ++i) {
    const double w = b[(i + 1) % 3] * b[(i + 2) % 3];
    sum = sum + (o.blend == Blend::Squared ? w * w : w);
  }
  return sum >= 1e-300;
}

void make_plan(const SideVertexSurface& s, size_t tri, const double* u, const double* v, size_t n, Plan& p) {
  p.n = n;
  p.m = 0;
  const bool valid_tri = tri < s.triangle_count();
  for (size_t k = 0; k < n; ++k) {
    const bool lane = valid_tri && u[k] >= 0.0 && v[k] >= 0.0 && u[k] + v[k] <= 1.0 + 1e-12 &&
                      inside(s.options(), u[k], v[k]);
    p.scalar[k] = !lane;
    if (lane) p.sample[p.m++] = uint8_t(k);
  }
  std::pair<double, uint8_t> order[kChunk];
  for (int i = 0; i < 3; ++i) {
    for (size_t k = 0; k < p.m; ++k) {
      const double uu = u[p.sample[k]], vv = v[p.sample[k]];
      const double b[3] = {(1.0 - uu) - vv, uu, vv};
      const double rest = b[(i + 1) % 3] + b[(i + 2) % 3];
      order[k] = {b[(i + 2) % 3] * (1.0 / rest), uint8_t(k)};
    }
    std::sort(order, order + p.m);
    size_t d = 0;
    for (size_t k = 0; k < p.m; ++k) {
      if (k == 0 || order[k].first != order[k - 1].first) p.t[i][d++] = order[k].first;
      p.index[i][order[k].second] = uint8_t(d - 1);
    }
    p.distinct[i] = d;
  }
}

// Block i's radial conics at the plan's distinct t, four per group.
template <bool S>
ISOFORM_JET_INLINE void build_conics(const SideVertexSurface& s, size_t tri, int i, Plan& p, Radial<S>* out) {
  const int j = (i + 1) % 3, k = (i + 2) % 3;
  const TriangleEdge te = s.triangle_edge(tri, i);
  const EdgePoly& e = s.edge_poly(size_t(te.edge));
  const double inv_ij = s.edge_inv_tension(size_t(s.triangle_edge(tri, k).edge));
  const double inv_ik = s.edge_inv_tension(size_t(s.triangle_edge(tri, j).edge));
  const bool automatic = inv_ij == 0.0 && inv_ik == 0.0;
  const size_t vi = size_t(s.triangle_vertex(tri, i));
  const V3d &b0 = s.vertex(vi), &n0 = s.vertex_normal(vi);
  const size_t d = p.distinct[i];
  for (size_t g = 0; 4 * g < d; ++g) {
    L t;
    for (int l = 0; l < 4; ++l) t[l] = p.t[i][std::min(4 * g + size_t(l), d - 1)];
    M bad{};
    lanes::V1<S> q, nq;
    lanes::edge_value<S>(e, te.reversed ? 1.0 - t : t, te.reversed ? -1.0 : 1.0, q, nq, bad);
    const J1<S> inv(inv_ij + t * (inv_ik - inv_ij), lanes::splat(inv_ik - inv_ij), L{});
    lanes::radial_conic<S>(b0, n0, q, nq, automatic ? nullptr : &inv, bad, out[g]);
    for (int l = 0; l < 4 && 4 * g + size_t(l) < d; ++l) p.bad_t[i][4 * g + size_t(l)] = bad[l] != 0;
  }
}

// Lane l of out is lane (index % 4) of conics[index / 4].
template <bool S>
ISOFORM_JET_INLINE Radial<S> gather(const Radial<S>* conics, const size_t (&index)[4]) {
  constexpr size_t kFields = sizeof(Radial<S>) / sizeof(L);
  static_assert(sizeof(Radial<S>) == kFields * sizeof(L), "Radial holds lanes only");
  const L* f[4];
  int l4[4];
  for (int l = 0; l < 4; ++l) {
    f[l] = reinterpret_cast<const L*>(&conics[index[l] / 4]);
    l4[l] = int(index[l] % 4);
  }
  Radial<S> r;
  L* o = reinterpret_cast<L*>(&r);
  for (size_t k = 0; k < kFields; ++k) o[k] = L{f[0][k][l4[0]], f[1][k][l4[1]], f[2][k][l4[2]], f[3][k][l4[3]]};
  return r;
}

template <bool S>
ISOFORM_JET_INLINE J2<S> variable(L x, int axis) {
  J2<S> j;
  j.v = x;
  j.d[axis] = lanes::splat(1.0);
  j.d[1 - axis] = L{};
  for (L& h : j.h) h = L{};
  return j;
}

// patch_point of fast_eval.h for four lane samples (positions k[l] among
// the plan's lane samples).
template <bool S>
ISOFORM_JET_INLINE V2<S> blend(const SideVertexSurface& s, size_t tri, const Plan& p, const Radial<S>* const* conics,
                               const double* u, const double* v, const size_t (&k)[4]) {
  L uu, vv;
  for (int l = 0; l < 4; ++l) {
    uu[l] = u[p.sample[k[l]]];
    vv[l] = v[p.sample[k[l]]];
  }
  J2<S> bary[3];
  bary[1] = variable<S>(uu, 0);
  bary[2] = variable<S>(vv, 1);
  bary[0].v = (1.0 - uu) - vv;
  bary[0].d[0] = bary[0].d[1] = lanes::splat(-1.0);
  for (L& h : bary[0].h) h = L{};
  J2<S> weight[3], sum;
  for (int i = 0; i < 3; ++i) {
    const J2<S> w = bary[(i + 1) % 3] * bary[(i + 2) % 3];
    weight[i] = s.options().blend == Blend::Squared ? w * w : w;
    sum = i == 0 ? weight[0] : sum + weight[i];
  }
  const J2<S> inv = lanes::reciprocal(sum);
  V2<S> out;
  for (int i = 0; i < 3; ++i) {
    const J2<S> rest = bary[(i + 1) % 3] + bary[(i + 2) % 3];
    const J2<S> t_local = bary[(i + 2) % 3] * lanes::reciprocal(rest);
    size_t at[4];
    for (int l = 0; l < 4; ++l) at[l] = p.index[i][k[l]];
    const Radial<S> c = gather<S>(conics[i], at);
    const V3d& b0 = s.vertex(size_t(s.triangle_vertex(tri, i)));
    const V2<S> block = lanes::radial_point<S>(b0, c, t_local, rest);
    const J2<S> wi = weight[i] * inv;
    const V2<S> term(wi * block.x, wi * block.y, wi * block.z);
    out = i == 0 ? term : V2<S>(out.x + term.x, out.y + term.y, out.z + term.z);
  }
  return out;
}

bool finite3(const std::array<double, 3>& a) {
  return std::isfinite(a[0]) && std::isfinite(a[1]) && std::isfinite(a[2]);
}

// Lane l of p into a sample, with evaluate_with's checks and normal.
template <bool S>
bool store(const V2<S>& p, int l, SurfaceSample& o) {
  const lanes::J2<S>* c[3] = {&p.x, &p.y, &p.z};
  for (int a = 0; a < 3; ++a) {
    o.point[size_t(a)] = c[a]->v[l];
    o.du[size_t(a)] = c[a]->d[0][l];
    o.dv[size_t(a)] = c[a]->d[1][l];
    o.duu[size_t(a)] = S ? c[a]->h[0][l] : 0.0;
    o.duv[size_t(a)] = S ? c[a]->h[1][l] : 0.0;
    o.dvv[size_t(a)] = S ? c[a]->h[2][l] : 0.0;
  }
  o.has_second = S;
  if (!finite3(o.point) || !finite3(o.du) || !finite3(o.dv)) return false;
  if (S && (!finite3(o.duu) || !finite3(o.duv) || !finite3(o.dvv))) return false;
  const V3d n = cross(V3d::from(o.du), V3d::from(o.dv));
  const double len = norm(n);
  if (!(len > 1e-300) || !std::isfinite(len)) return false;
  o.normal = {n.x / len, n.y / len, n.z / len};
  return true;
}

// The lane work of one planned chunk: conics, then points of the samples
// whose three conics are all good.
template <bool S>
ISOFORM_JET_INLINE void run_lanes(const SideVertexSurface& s, size_t tri, Plan& p, const double* u, const double* v,
                                  SurfaceSample* out, bool* ok) {
  Radial<S> conics[3][kGroups];
  for (int i = 0; i < 3; ++i) build_conics<S>(s, tri, i, p, conics[i]);
  const Radial<S>* by_block[3] = {conics[0], conics[1], conics[2]};
  size_t good[kChunk];
  size_t g = 0;
  for (size_t k = 0; k < p.m; ++k) {
    const bool bad = p.bad_t[0][p.index[0][k]] || p.bad_t[1][p.index[1][k]] || p.bad_t[2][p.index[2][k]];
    if (bad) p.scalar[p.sample[k]] = true;
    else good[g++] = k;
  }
  for (size_t q = 0; q < g; q += 4) {
    size_t k[4];
    for (int l = 0; l < 4; ++l) k[l] = good[std::min(q + size_t(l), g - 1)];
    const V2<S> pt = blend<S>(s, tri, p, by_block, u, v, k);
    for (int l = 0; l < 4 && q + size_t(l) < g; ++l) {
      const size_t at = p.sample[k[l]];
      ok[at] = store<S>(pt, l, out[at]);
    }
  }
}

template <bool S>
__attribute__((target("avx2,fma"))) void run_lanes_avx2(const SideVertexSurface& s, size_t tri, Plan& p,
                                                         const double* u, const double* v, SurfaceSample* out,
                                                         bool* ok) {
  run_lanes<S>(s, tri, p, u, v, out, ok);
}

template <bool S>
void run_lanes_plain(const SideVertexSurface& s, size_t tri, Plan& p, const double* u, const double* v,
                     SurfaceSample* out, bool* ok) {
  run_lanes<S>(s, tri, p, u, v, out, ok);
}

bool has_avx2() {
  static const bool yes = __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
  return yes;
}

}  // namespace

void evaluate_batch(const SideVertexSurface& s, size_t tri, const double* u, const double* v, size_t n,
                    SurfaceSample* out, bool* ok, bool second, BatchIsa isa) {
  const bool avx2 = isa == BatchIsa::Best && has_avx2();
  Plan plan;
  for (size_t start = 0; start < n; start += kChunk) {
    const size_t c = std::min(kChunk, n - start);
    const double *cu = u + start, *cv = v + start;
    make_plan(s, tri, cu, cv, c, plan);
    if (plan.m > 0) {
      if (second) (avx2 ? run_lanes_avx2<true> : run_lanes_plain<true>)(s, tri, plan, cu, cv, out + start, ok + start);
      else (avx2 ? run_lanes_avx2<false> : run_lanes_plain<false>)(s, tri, plan, cu, cv, out + start, ok + start);
    }
    for (size_t k = 0; k < c; ++k)
      if (plan.scalar[k]) ok[start + k] = s.evaluate_order(tri, cu[k], cv[k], out[start + k], second);
  }
}

}  // namespace isoform::patch

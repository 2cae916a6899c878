// Batch evaluation of the side-vertex patch (batch_eval.h): a plan per chunk
// of samples (which go the scalar way, the distinct t of each building
// block), the radial conics of the distinct t four at a time, then the
// patch points four at a time.
#include "batch_eval.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
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

using detail::BatchChunk;
constexpr size_t kChunk = detail::kBatchChunk;

// What one triangle's run adds to a chunk's plan.
struct Run {
  bool bad_t[3][kChunk];  // the t's conic took a rare branch
  bool scalar[kChunk];    // position -> scalar path
};

// The blend's weight sum as patch_point computes it (false: a corner).
bool inside(Blend blend, double u, double v) {
  const double b[3] = {(1.0 - u) - v, u, v};
  double sum = 0.0;
  for (int i = 0; i < 3; ++i) {
    const double w = b[(i + 1) % 3] * b[(i + 2) % 3];
    sum = sum + (blend == Blend::Squared ? w * w : w);
  }
  return sum >= 1e-300;
}

void make_chunk(Blend blend, const double* u, const double* v, size_t start, size_t n, BatchChunk& p) {
  p.start = start;
  p.n = n;
  p.m = 0;
  u += start;
  v += start;
  for (size_t k = 0; k < n; ++k) {
    p.lane[k] = u[k] >= 0.0 && v[k] >= 0.0 && u[k] + v[k] <= 1.0 + 1e-12 && inside(blend, u[k], v[k]);
    if (p.lane[k]) p.sample[p.m++] = uint8_t(k);
  }
  std::pair<double, uint8_t> order[kChunk];
  for (int i = 0; i < 3; ++i) {
    for (size_t k = 0; k < p.m; ++k) {
      const double uu = u[p.sample[k]], vv = v[p.sample[k]];
      const double b[3] = {(1.0 - uu) - vv, uu, vv};
      const double rest = b[(i + 1) % 3] + b[(i + 2) % 3];
      // As fast_eval.h's t_local (a jet quotient: times the reciprocal).
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

// One radial conic (a Radial's 30 lane fields, one lane's worth) as 32
// consecutive doubles: four-by-four transposes move conics between lanes
// and records, so a lane group can gather any four of them.
struct alignas(32) Record {
  L f[8];
};
constexpr int kFields = 30;

// Block i's radial conics at the plan's distinct t, four per group, into
// one record per t.
template <bool S>
ISOFORM_JET_INLINE void build_conics(const SideVertexSurface& s, size_t tri, int i, const BatchChunk& p, Run& run,
                                     Record* out) {
  static_assert(sizeof(Radial<S>) == kFields * sizeof(L), "Radial holds 30 lane fields");
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
    Radial<S> c;
    lanes::radial_conic<S>(b0, n0, q, nq, automatic ? nullptr : &inv, bad, c);
    const L* f = reinterpret_cast<const L*>(&c);
    for (int r = 0; r < 8; ++r) {
      L a0 = f[4 * r], a1 = f[4 * r + 1], a2 = 4 * r + 2 < kFields ? f[4 * r + 2] : L{},
        a3 = 4 * r + 3 < kFields ? f[4 * r + 3] : L{};
      lanes::transpose4(a0, a1, a2, a3);
      out[4 * g].f[r] = a0;
      out[4 * g + 1].f[r] = a1;
      out[4 * g + 2].f[r] = a2;
      out[4 * g + 3].f[r] = a3;
    }
    for (int l = 0; l < 4 && 4 * g + size_t(l) < d; ++l) run.bad_t[i][4 * g + size_t(l)] = bad[l] != 0;
  }
}

// Lane l of the result is record index[l].
template <bool S>
ISOFORM_JET_INLINE void gather(const Record* records, const size_t (&index)[4], Radial<S>& out) {
  L* o = reinterpret_cast<L*>(&out);
  for (int r = 0; r < 8; ++r) {
    L a0 = records[index[0]].f[r], a1 = records[index[1]].f[r], a2 = records[index[2]].f[r],
      a3 = records[index[3]].f[r];
    lanes::transpose4(a0, a1, a2, a3);
    o[4 * r] = a0;
    o[4 * r + 1] = a1;
    if (4 * r + 2 < kFields) o[4 * r + 2] = a2;
    if (4 * r + 3 < kFields) o[4 * r + 3] = a3;
  }
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
ISOFORM_JET_INLINE V2<S> blend(const SideVertexSurface& s, size_t tri, const BatchChunk& p, const Record* const* conics,
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
    Radial<S> c;
    gather<S>(conics[i], at, c);
    const V3d& b0 = s.vertex(size_t(s.triangle_vertex(tri, i)));
    const V2<S> block = lanes::radial_point<S>(b0, c, t_local, rest);
    const J2<S> wi = weight[i] * inv;
    const V2<S> term(wi * block.x, wi * block.y, wi * block.z);
    out = i == 0 ? term : V2<S>(out.x + term.x, out.y + term.y, out.z + term.z);
  }
  return out;
}

// Per lane: every value finite (x - x is 0 exactly for finite x).
ISOFORM_JET_INLINE M finite_lanes(L x) { return (x - x) == 0.0; }

// The four samples of p, with evaluate_with's checks (finite values, a
// normal): the unit normal and the lanes that pass.
template <bool S>
ISOFORM_JET_INLINE M finish(const V2<S>& p, L (&normal)[3]) {
  const lanes::J2<S>* c[3] = {&p.x, &p.y, &p.z};
  M fine = ~M{};
  for (int a = 0; a < 3; ++a) {
    fine &= finite_lanes(c[a]->v) & finite_lanes(c[a]->d[0]) & finite_lanes(c[a]->d[1]);
    if constexpr (S) fine &= finite_lanes(c[a]->h[0]) & finite_lanes(c[a]->h[1]) & finite_lanes(c[a]->h[2]);
  }
  const L nx = p.y.d[0] * p.z.d[1] - p.z.d[0] * p.y.d[1];
  const L ny = p.z.d[0] * p.x.d[1] - p.x.d[0] * p.z.d[1];
  const L nz = p.x.d[0] * p.y.d[1] - p.y.d[0] * p.x.d[1];
  const L len = lanes::lane_sqrt(nx * nx + ny * ny + nz * nz);
  fine &= (len > 1e-300) & finite_lanes(len);
  normal[0] = nx / len;
  normal[1] = ny / len;
  normal[2] = nz / len;
  return fine;
}

// The four samples of p with their normals into out[at[l]]: the 21
// doubles of a SurfaceSample (point, normal, du, dv, duu, duv, dvv) as
// lane vectors, transposed four at a time into each sample's memory.
template <bool S>
ISOFORM_JET_INLINE void store(const V2<S>& p, const L (&normal)[3], SurfaceSample* const (&at)[4]) {
  static_assert(sizeof(std::array<double, 3>) == 24 && offsetof(SurfaceSample, normal) == 24 &&
                    offsetof(SurfaceSample, du) == 48 && offsetof(SurfaceSample, dvv) == 144,
                "SurfaceSample holds 21 consecutive doubles");
  const lanes::J2<S>* c[3] = {&p.x, &p.y, &p.z};
  L f[24];
  for (int a = 0; a < 3; ++a) {
    f[a] = c[a]->v;
    f[3 + a] = normal[a];
    f[6 + a] = c[a]->d[0];
    f[9 + a] = c[a]->d[1];
    for (int h = 0; h < 3; ++h) f[12 + 3 * h + a] = S ? c[a]->h[h] : L{};
  }
  for (int r = 0; r < 5; ++r) {
    L a0 = f[4 * r], a1 = f[4 * r + 1], a2 = f[4 * r + 2], a3 = f[4 * r + 3];
    lanes::transpose4(a0, a1, a2, a3);
    const L rows[4] = {a0, a1, a2, a3};
    for (int l = 0; l < 4; ++l) std::memcpy(reinterpret_cast<double*>(at[l]) + 4 * r, &rows[l], sizeof(L));
  }
  for (int l = 0; l < 4; ++l) {
    at[l]->dvv[2] = f[20][l];
    at[l]->has_second = S;
  }
}

// The lane work of one planned chunk: conics, then points of the samples
// whose three conics are all good.
template <bool S>
ISOFORM_JET_INLINE void run_lanes(const SideVertexSurface& s, size_t tri, const BatchChunk& p, Run& run,
                                  const double* u, const double* v, SurfaceSample* out, bool* ok) {
  Record conics[3][kChunk];
  for (int i = 0; i < 3; ++i) build_conics<S>(s, tri, i, p, run, conics[i]);
  const Record* by_block[3] = {conics[0], conics[1], conics[2]};
  size_t good[kChunk];
  size_t g = 0;
  for (size_t k = 0; k < p.m; ++k) {
    const bool bad = run.bad_t[0][p.index[0][k]] || run.bad_t[1][p.index[1][k]] || run.bad_t[2][p.index[2][k]];
    if (bad) run.scalar[p.sample[k]] = true;
    else good[g++] = k;
  }
  for (size_t q = 0; q < g; q += 4) {
    size_t k[4];
    for (int l = 0; l < 4; ++l) k[l] = good[std::min(q + size_t(l), g - 1)];
    const V2<S> pt = blend<S>(s, tri, p, by_block, u, v, k);
    L normal[3];
    const M fine = finish<S>(pt, normal);
    // NOTE: padding lanes repeat the last sample: they write its values again.
    SurfaceSample* const to[4] = {&out[p.sample[k[0]]], &out[p.sample[k[1]]], &out[p.sample[k[2]]],
                                  &out[p.sample[k[3]]]};
    store<S>(pt, normal, to);
    for (int l = 0; l < 4; ++l) ok[p.sample[k[l]]] = fine[l] != 0;
  }
}

template <bool S>
__attribute__((target("avx2,fma"))) void run_lanes_avx2(const SideVertexSurface& s, size_t tri, const BatchChunk& p,
                                                         Run& run, const double* u, const double* v,
                                                         SurfaceSample* out, bool* ok) {
  run_lanes<S>(s, tri, p, run, u, v, out, ok);
}

template <bool S>
void run_lanes_plain(const SideVertexSurface& s, size_t tri, const BatchChunk& p, Run& run, const double* u,
                     const double* v, SurfaceSample* out, bool* ok) {
  run_lanes<S>(s, tri, p, run, u, v, out, ok);
}

bool has_avx2() {
  static const bool yes = __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
  return yes;
}

}  // namespace

BatchPlan::BatchPlan(const PatchOptions& options, const double* u, const double* v, size_t n)
    : blend_(options.blend), u_(u, u + n), v_(v, v + n) {
  for (size_t start = 0; start < n; start += kChunk) {
    chunks_.emplace_back();
    make_chunk(blend_, u, v, start, std::min(kChunk, n - start), chunks_.back());
  }
}

void evaluate_batch(const SideVertexSurface& s, size_t tri, const BatchPlan& plan, SurfaceSample* out, bool* ok,
                    bool second, BatchIsa isa) {
  if (plan.blend() != s.options().blend) {
    evaluate_batch(s, tri, plan.u(), plan.v(), plan.size(), out, ok, second, isa);
    return;
  }
  const bool avx2 = isa == BatchIsa::Best && has_avx2();
  const bool valid = tri < s.triangle_count();
  Run run;
  for (const BatchChunk& c : plan.chunks()) {
    const double *cu = plan.u() + c.start, *cv = plan.v() + c.start;
    SurfaceSample* co = out + c.start;
    bool* cok = ok + c.start;
    for (size_t k = 0; k < c.n; ++k) run.scalar[k] = !valid || !c.lane[k];
    if (valid && c.m > 0) {
      if (second) (avx2 ? run_lanes_avx2<true> : run_lanes_plain<true>)(s, tri, c, run, cu, cv, co, cok);
      else (avx2 ? run_lanes_avx2<false> : run_lanes_plain<false>)(s, tri, c, run, cu, cv, co, cok);
    }
    for (size_t k = 0; k < c.n; ++k)
      if (run.scalar[k]) cok[k] = s.evaluate_order(tri, cu[k], cv[k], co[k], second);
  }
}

void evaluate_batch(const SideVertexSurface& s, size_t tri, const double* u, const double* v, size_t n,
                    SurfaceSample* out, bool* ok, bool second, BatchIsa isa) {
  evaluate_batch(s, tri, BatchPlan(s.options(), u, v, n), out, ok, second, isa);
}

}  // namespace isoform::patch

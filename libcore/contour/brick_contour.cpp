// Contouring one brick with the trilinear-consistent cell method or the six
// tetrahedra (Hamann 1991, Section 3.2), with Zucker-Hummel normals
// interpolated along edges (3.18) and inside cells (3.19).
#include "brick_contour.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "../errors.h"
#include "cell_polygons.h"
#include "cell_table.h"
#include "gradient.h"
#include "tetra.h"

namespace isoform {

namespace {
constexpr double kNearSample = 1e-3;  // fraction of an edge

// Bit i set when f[i] >= above_at, for i < n (at most 64); zero is set when
// some f[i] == equal_to. Four samples at a time where SSE is there: the
// same comparisons, so the same bits.
uint64_t row_mask(const float* f, int n, float above_at, float equal_to, bool& zero) {
  uint64_t above = 0;
  int i = 0;
#if defined(__SSE2__)
  const __m128 at = _mm_set1_ps(above_at), eq = _mm_set1_ps(equal_to);
  __m128 any_equal = _mm_setzero_ps();
  for (; i + 4 <= n; i += 4) {
    const __m128 x = _mm_loadu_ps(f + i);
    above |= uint64_t(_mm_movemask_ps(_mm_cmpge_ps(x, at))) << i;
    any_equal = _mm_or_ps(any_equal, _mm_cmpeq_ps(x, eq));
  }
  zero |= _mm_movemask_ps(any_equal) != 0;
#endif
  for (; i < n; ++i) {
    above |= uint64_t(f[i] >= above_at) << i;
    zero |= f[i] == equal_to;
  }
  return above;
}

}  // namespace

uint64_t edge_key(int x, int y, int z, int slot) {
  constexpr int64_t half = int64_t(1) << 19;
  const int64_t c[3] = {x + half, y + half, z + half};
  for (int64_t v : c)
    if (v < 0 || v >= 2 * half)
      throw Unsupported("index coordinate beyond +-524288: isoform's vertex keys hold 20 bits per axis");
  return (uint64_t(c[0]) << 43) | (uint64_t(c[1]) << 23) | (uint64_t(c[2]) << 3) | uint64_t(slot);
}

BrickContourer::BrickContourer(const Affine& index_to_world, double isovalue, ContourMethod method)
    : xform_(index_to_world), iso_(isovalue), method_(method),
      slots_(method == ContourMethod::Tetra ? 7 : 3) {
  index_to_world.cofactors(cofactor_);
  four_gradients_ = has_zucker_hummel_four();
  normal_sign_ = index_to_world.determinant() < 0 ? -1.0 : 1.0;
  // For float samples f: f >= iso_above_ exactly when double(f) >= iso_,
  // and f == iso_float_ exactly when double(f) == iso_ (NaN when no float is).
  constexpr float big = std::numeric_limits<float>::max();
  const float nearest = float(std::clamp(isovalue, -double(big), double(big)));
  iso_above_ = isovalue > double(big) ? HUGE_VALF
               : double(nearest) >= isovalue ? nearest
                                             : std::nextafter(nearest, HUGE_VALF);
  iso_float_ = double(nearest) == isovalue ? nearest : std::numeric_limits<float>::quiet_NaN();
}

double BrickContourer::moved(int i, int j, int k) const {
  // Remark 3.8: a sample equal to the isovalue counts as above and moves up
  // by a thousandth of the smallest non-zero difference among its six
  // neighbours. The move depends on the sample's neighbourhood only, so every
  // cell and every brick that shares the sample moves it alike, and the
  // vertices it makes stay a thousandth of an edge from the sample instead of
  // collapsing onto it.
  const Brick& b = *brick_;
  const double v = double(b.value(i, j, k)) - iso_;
  if (v != 0.0) return v;
  static const int step[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  double smallest = std::numeric_limits<double>::infinity();
  for (const auto& s : step) {
    if (!b.is_defined(i + s[0], j + s[1], k + s[2])) continue;
    const double d = std::abs(double(b.value(i + s[0], j + s[1], k + s[2])) - iso_);
    if (d > 0.0 && d < smallest) smallest = d;
  }
  return std::isfinite(smallest) ? 1e-3 * smallest : 1e-9 * std::max(1.0, std::abs(iso_));
}

bool BrickContourer::prepare(const Brick& brick) {
  brick_ = &brick;
  for (int a = 0; a < 3; ++a) n_[a] = brick.cells[a] + 1;
  if (n_[0] > 64) throw Unsupported("bricks of more than 63 cells along x");
  all_defined_ = std::find(brick.defined.begin(), brick.defined.end(), uint8_t(0)) == brick.defined.end();
  above_.resize(size_t(n_[1]) * size_t(n_[2]));
  undefined_.resize(above_.size());
  const uint64_t full = n_[0] == 64 ? ~uint64_t(0) : (uint64_t(1) << n_[0]) - 1;
  uint64_t any_above = 0, any_below = 0;
  bool zero = false;
  for (int k = 0; k < n_[2]; ++k)
    for (int j = 0; j < n_[1]; ++j) {
      const size_t row = brick.at(0, j, k);
      const float* f = &brick.samples[row];
      // Above: f - iso > 0, or f = iso, which moves up (Remark 3.8).
      uint64_t undefined = 0;
      uint64_t above = row_mask(f, n_[0], iso_above_, iso_float_, zero);
      if (!all_defined_) {
        const uint8_t* def = &brick.defined[row];
        for (int i = 0; i < n_[0]; ++i) undefined |= uint64_t(def[i] == 0) << i;
        above &= ~undefined;
      }
      const size_t r = size_t(k) * size_t(n_[1]) + size_t(j);
      above_[r] = above;
      undefined_[r] = undefined;
      any_above |= above;
      any_below |= full & ~above & ~undefined;
    }
  // Without samples to move, g is f - iso, read from the brick as needed.
  moved_samples_ = zero;
  if (zero) {
    g_.resize(size_t(n_[0]) * size_t(n_[1]) * size_t(n_[2]));
    double* g = g_.data();
    for (int k = 0; k < n_[2]; ++k)
      for (int j = 0; j < n_[1]; ++j)
        for (int i = 0; i < n_[0]; ++i, ++g) {
          const double v = double(brick.value(i, j, k)) - iso_;
          *g = v != 0.0 ? v : moved(i, j, k);
        }
  }
  return any_above != 0 && any_below != 0;
}

double BrickContourer::g_at(int i, int j, int k) const {
  if (moved_samples_) return g_[(size_t(k) * size_t(n_[1]) + size_t(j)) * size_t(n_[0]) + size_t(i)];
  return double(brick_->samples[brick_->at(i, j, k)]) - iso_;
}

void BrickContourer::gather(int i, int j, int k, double g[8]) const {
  for (int c = 0; c < 8; ++c) g[c] = g_at(i + (c & 1), j + ((c >> 1) & 1), k + (c >> 2));
}

const Vec3d& BrickContourer::gradient(int i, int j, int k) {
  const size_t at = (size_t(k) * size_t(n_[1]) + size_t(j)) * size_t(n_[0]) + size_t(i);
  if (!has_grad_[at]) {
    const Brick& b = *brick_;
    const Index3 d = b.dims();
    const size_t row = size_t(d[0]), slice = size_t(d[0]) * size_t(d[1]);
    // NOTE: four samples of the row at a time where the processor allows
    // (the same bits): the surface's samples come in runs along rows.
    const int first = i & ~3;
    if (all_defined_ && four_gradients_ && first + 3 < n_[0]) {
      zucker_hummel_four(&b.samples[b.at(first, j, k)], row, slice, &grad_[at - size_t(i - first)]);
      for (size_t l = at - size_t(i - first); l < at - size_t(i - first) + 4; ++l) has_grad_[l] = 1;
      return grad_[at];
    }
    grad_[at] = all_defined_ ? zucker_hummel_inside(&b.samples[b.at(i, j, k)], row, slice) : zucker_hummel(b, i, j, k);
    has_grad_[at] = 1;
  }
  return grad_[at];
}

int32_t BrickContourer::add_vertex(const Vec3d& index_pos, const Vec3d& grad) {
  // Affine::apply and apply_normal, with the normal map's signed cofactors
  // computed once (the constructor): the same arithmetic, bit for bit.
  const double(&m)[3][4] = xform_.m;
  Vec3d w, n;
  for (int a = 0; a < 3; ++a) {
    w[a] = m[a][0] * index_pos[0] + m[a][1] * index_pos[1] + m[a][2] * index_pos[2] + m[a][3];
    n[a] = normal_sign_ * (cofactor_[a][0] * grad[0] + cofactor_[a][1] * grad[1] + cofactor_[a][2] * grad[2]);
  }
  return push_vertex(w.data(), n.data());
}

int32_t BrickContourer::push_vertex(const double* point, const double* grad) {
  // Six single appends: each an inline capacity check, where a range insert
  // is an out-of-line call per vertex.
  std::vector<float>& v = out_->vertices;
  for (int a = 0; a < 3; ++a) v.push_back(float(point[a]));
  for (int a = 0; a < 3; ++a) v.push_back(float(grad[a]));
  out_->on_seam.push_back(0);
  for (int q = 0; q < 4; ++q) out_->vertex_sides.push_back(-1);
  return int32_t(v.size() / 6 - 1);
}

bool BrickContourer::run(const Brick& brick, BrickMesh& out, BrickStores& store) {
  out = BrickMesh();
  if (!prepare(brick)) return false;
  out_ = &work_;
  work_.vertices.clear();
  work_.triangles.clear();
  work_.fan_links.clear();
  work_.on_seam.clear();
  work_.seam_edges = 0;
  work_.pair_end = 0;
  work_.lone_sides.clear();
  work_.seam_sides.clear();
  work_.vertex_sides.clear();
  work_.shared.clear();
  work_.stats = ContourStats();
  const size_t count = size_t(n_[0]) * size_t(n_[1]) * size_t(n_[2]);
  grad_.resize(count);
  has_grad_.assign(count, 0);
  slot_vertex_.assign(count * size_t(slots_), -1);
  const size_t n1 = size_t(n_[1]);
  const uint64_t cell_bits = (uint64_t(1) << brick.cells[0]) - 1;  // lower corners of a row's cells
  double g[8];
  for (int k = 0; k < brick.cells[2]; ++k)
    for (int j = 0; j < brick.cells[1]; ++j) {
      // The four rows of corners of the cell row (j, k), as bit masks.
      const size_t r = size_t(k) * n1 + size_t(j);
      const uint64_t a00 = above_[r], a10 = above_[r + 1], a01 = above_[r + n1], a11 = above_[r + n1 + 1];
      const uint64_t u = undefined_[r] | undefined_[r + 1] | undefined_[r + n1] | undefined_[r + n1 + 1];
      const uint64_t all = a00 & a10 & a01 & a11, any = a00 | a10 | a01 | a11;
      // A cell is skipped when its 8 corners agree (both its corner columns
      // all above, or both all below) or when one of them is undefined.
      const uint64_t skip = ((all & (all >> 1)) | ~(any | (any >> 1)) | u | (u >> 1)) & cell_bits;
      if (skip == cell_bits) continue;
      for (int i = 0; i < brick.cells[0]; ++i) {
        if ((skip >> i) & 1) continue;
        const int above = int((a00 >> i) & 3) | int(((a10 >> i) & 3) << 2) | int(((a01 >> i) & 3) << 4) |
                          int(((a11 >> i) & 3) << 6);
        gather(i, j, k, g);
        if (method_ == ContourMethod::Cells)
          contour_cell_trilinear(i, j, k, g, above);
        else
          contour_cell_tetra(i, j, k, g);
      }
    }
  // Sides still waiting: the cell across their face was not contoured.
  for (const int32_t e : work_.vertex_sides)
    if (e >= 0) work_.lone_sides.push_back(uint32_t(e));
  const size_t nv = work_.vertices.size() / 6;
  if (nv >= (size_t(1) << 31) || work_.triangles.size() >= (size_t(1) << 31))
    throw Unsupported("a brick with more than 2^31 vertices");
  out.vertices = store.vertices.copy(work_.vertices.data(), work_.vertices.size());
  out.triangles = store.faces.copy(work_.triangles.data(), work_.triangles.size());
  out.fan_links = store.faces.copy(work_.fan_links.data(), work_.fan_links.size());
  out.seam_count = work_.seam_edges;
  if (method_ == ContourMethod::Cells) {
    BrickSides& sides = out.sides;
    sides.known = true;
    sides.pairs = store.faces.copy(work_.side_pairs.data(), work_.pair_end);
    sides.pair_count = uint32_t(work_.pair_end / 2);
    sides.lone = store.faces.copy(work_.lone_sides.data(), work_.lone_sides.size());
    sides.lone_count = uint32_t(work_.lone_sides.size());
    sides.seam = store.faces.copy(work_.seam_sides.data(), work_.seam_sides.size());
  }
  out.shared = store.faces.copy(work_.shared.data(), work_.shared.size());
  out.vertex_count = uint32_t(nv);
  out.triangle_count = uint32_t(work_.triangles.size() / 3);
  out.shared_count = uint32_t(work_.shared.size());
  const ContourStats& c = work_.stats;
  out.counts = BrickCounts{int32_t(c.ambiguous_faces), int32_t(c.degenerate_saddles), int32_t(c.extra_points),
                           int32_t(c.centroid_points), int32_t(c.near_sample_points)};
  out_ = nullptr;
  return true;
}

namespace {

// For the edge between corners p and q of a cell (axis edge, face diagonal
// or cell diagonal): the canonical direction and the corner and slot of its
// key, so that every cell (and brick) that uses the edge computes the same
// point from the same two values.
struct EdgeWay {
  uint8_t start, end, slot, key_corner;
};

EdgeWay edge_way(int p, int q) {
  const int diff = p ^ q;
  const int bits = (diff & 1) + ((diff >> 1) & 1) + ((diff >> 2) & 1);
  int start = p, end = q, slot = 0, key_corner = 0;
  if (bits == 1) {
    if (p & diff) std::swap(start, end);
    slot = diff == 1 ? 0 : diff == 2 ? 1 : 2;
    key_corner = start;
  } else if (bits == 2) {
    const int a = diff == 6 ? 0 : diff == 5 ? 1 : 2;  // the face's normal axis
    const int lo_axis_bit = diff & -diff;              // the lower tangential axis
    if (!(start & lo_axis_bit)) std::swap(start, end);
    slot = 3 + a;
    key_corner = p & (1 << a);
  } else {
    if (start != 1) std::swap(start, end);
    slot = 6;
    key_corner = 0;
  }
  return {uint8_t(start), uint8_t(end), uint8_t(slot), uint8_t(key_corner)};
}

const EdgeWay& edge_way_table(int p, int q) {
  struct Table {
    EdgeWay way[8][8];
    Table() {
      for (int a = 0; a < 8; ++a)
        for (int b = 0; b < 8; ++b) way[a][b] = a == b ? EdgeWay{} : edge_way(a, b);
    }
  };
  static const Table table;
  return table.way[p][q];
}

// The corners of each of the 12 cell edges (cell_table.h), lower first.
const std::array<int, 2>& cell_edge_corners(int e) {
  struct Table {
    std::array<int, 2> corners[12];
    Table() {
      for (int m = 0; m < 12; ++m) corners[m] = cell::edge_corners(m);
    }
  };
  static const Table table;
  return table.corners[e];
}

}  // namespace

int32_t BrickContourer::edge_vertex(int ci, int cj, int ck, int p, int q) {
  const EdgeWay& way = edge_way_table(p, q);
  const int start = way.start, end = way.end, slot = way.slot, key_corner = way.key_corner;
  const int kx = ci + (key_corner & 1), ky = cj + ((key_corner >> 1) & 1), kz = ck + (key_corner >> 2);
  const size_t at =
      ((size_t(kz) * size_t(n_[1]) + size_t(ky)) * size_t(n_[0]) + size_t(kx)) * size_t(slots_) + size_t(slot);
  if (slot_vertex_[at] >= 0) return slot_vertex_[at];

  const int sx = ci + (start & 1), sy = cj + ((start >> 1) & 1), sz = ck + (start >> 2);
  const int ex = ci + (end & 1), ey = cj + ((end >> 1) & 1), ez = ck + (end >> 2);
  const double gs = g_at(sx, sy, sz);
  const double ge = g_at(ex, ey, ez);
  // NOTE: a crossing closer than a thousandth of the edge to a sample is
  // held at that distance, so that the several vertices around a sample
  // whose value is within rounding of the isovalue stay distinct in float
  // output instead of making zero-area triangles.
  double t = gs / (gs - ge);
  if (t < kNearSample || t > 1.0 - kNearSample) {
    t = std::clamp(t, kNearSample, 1.0 - kNearSample);
    ++out_->stats.near_sample_points;
  }
  const Index3& o = brick_->origin;
  const Vec3d pos{o[0] + sx + t * (ex - sx), o[1] + sy + t * (ey - sy), o[2] + sz + t * (ez - sz)};
  const Vec3d& a = gradient(sx, sy, sz);
  const Vec3d& b = gradient(ex, ey, ez);
  const Vec3d grad{(1 - t) * a[0] + t * b[0], (1 - t) * a[1] + t * b[1], (1 - t) * a[2] + t * b[2]};
  const int32_t id = add_vertex(pos, grad);
  slot_vertex_[at] = id;

  // Shared with another brick when a cell using the edge lies outside this one.
  const int key[3] = {kx, ky, kz};
  bool shared = false;
  for (int ax = 0; ax < 3; ++ax) {
    const bool on_side = key[ax] == 0 || key[ax] == brick_->cells[ax];
    if ((slot < 3 && ax != slot) || (slot >= 3 && slot < 6 && ax == slot - 3)) shared |= on_side;
  }
  if (shared) {
    out_->shared.emplace_back(edge_key(o[0] + kx, o[1] + ky, o[2] + kz, slot), id);
    out_->on_seam[size_t(id)] = 1;
  }
  return id;
}

void BrickContourer::contour_cell_trilinear(int i, int j, int k, const double g[8], int above) {
  const CellPolygons* table = unambiguous_cell_polygons(above);
  CellPolygons decided;
  if (!table) {
    cell_polygons(g, decided);
    out_->stats.ambiguous_faces += decided.ambiguous_lower_faces;
    out_->stats.degenerate_saddles += decided.degenerate_lower_saddles;
  }
  const CellPolygons& cp = table ? *table : decided;
  for (int p = 0; p < cp.count; ++p) {
    const CellPolygon& poly = cp.polygons[p];
    int32_t ids[12];
    for (int m = 0; m < poly.size; ++m) {
      const std::array<int, 2>& ec = cell_edge_corners(poly.edges[m]);
      ids[m] = edge_vertex(i, j, k, ec[0], ec[1]);
    }
    std::vector<int32_t>& tri = out_->triangles;
    if (poly.double_face < 0) {
      // Theorem 3.4 (i): with at most one segment per face every
      // triangulation keeps Condition 3.1; a fan is one.
      add_fan(ids, poly.size, &poly);
      continue;
    }
    // Theorem 3.5: fan from an extra point off the double face.
    std::array<double, 3> uvw;
    int32_t centre;
    if (extra_point(g, poly, uvw)) {
      Vec3d grad{0, 0, 0};
      for (int c = 0; c < 8; ++c) {
        const double wgt = ((c & 1) ? uvw[0] : 1 - uvw[0]) * (((c >> 1) & 1) ? uvw[1] : 1 - uvw[1]) *
                           ((c >> 2) ? uvw[2] : 1 - uvw[2]);
        const Vec3d& gc = gradient(i + (c & 1), j + ((c >> 1) & 1), k + (c >> 2));
        for (int a = 0; a < 3; ++a) grad[a] += wgt * gc[a];
      }
      const Index3& o = brick_->origin;
      centre = add_vertex({o[0] + i + uvw[0], o[1] + j + uvw[1], o[2] + k + uvw[2]}, grad);
      ++out_->stats.extra_points;
    } else {
      centre = add_centroid(ids, poly.size);
      ++out_->stats.centroid_points;
    }
    // Triangle m's spoke (ids[m + 1], centre) is the next one's first; the
    // spoke to ids[0] joins the last triangle to the first; side m is edge
    // 0 of triangle m. Only sides can be seam edges (the centre is this
    // cell's own).
    const uint32_t t0 = uint32_t(tri.size() / 3), n = uint32_t(poly.size);
    for (int m = 0; m < poly.size; ++m) {
      tri.insert(tri.end(), {ids[m], ids[(m + 1) % poly.size], centre});
      out_->fan_links.push_back(m + 1 < poly.size ? fan_link(1, 2) : 0);
    }
    room_for_sides(poly.size);
    for (int m = 0; m < poly.size; ++m) add_side(ids, poly, m, 3 * (t0 + uint32_t(m)));
    uint32_t* spoke = &out_->side_pairs[out_->pair_end];
    spoke[0] = 3 * t0 + 2;
    spoke[1] = 3 * (t0 + n - 1) + 1;
    out_->pair_end += 2;
  }
}

namespace {

// Which of the 4 cell faces around a grid edge face f of a cell is, seen
// from the cell's edge e on it (0-3, the same from both cells that share
// the face), or -1 when e is not on f.
struct SideSlots {
  int8_t slot[12][6] = {};
  constexpr SideSlots() {
    for (int e = 0; e < 12; ++e)
      for (int f = 0; f < 6; ++f) {
        const int along = e / 4, axis = f / 2, o1 = (along + 1) % 3, o2 = (along + 2) % 3;
        const int first = o1 < o2 ? o1 : o2, across = 3 - along - axis;
        // The edge's coordinates on the other two axes, lower axis first.
        const int at_axis = axis == first ? e & 1 : (e >> 1) & 1;
        const int at_across = across == first ? e & 1 : (e >> 1) & 1;
        slot[e][f] = int8_t(axis == along || at_axis != f % 2 ? -1 : 2 * (axis == first ? 0 : 1) + at_across);
      }
  }
};
constexpr SideSlots kSideSlots;

}  // namespace

void BrickContourer::room_for_sides(int n) {
  std::vector<uint32_t>& pairs = out_->side_pairs;
  const size_t need = out_->pair_end + 2 * size_t(n) + 2;
  if (pairs.size() < need) pairs.resize(std::max(need, 2 * pairs.size()));
}

void BrickContourer::add_side(const int32_t* ids, const CellPolygon& poly, int m, uint32_t edge) {
  const int next = m + 1 < poly.size ? m + 1 : 0;
  const int32_t a = ids[m], b = ids[next];
  // Edges whose two ends other bricks may use become SeamEdge records.
  const std::vector<uint8_t>& seam = out_->on_seam;
  if (seam[size_t(a)] & seam[size_t(b)]) {
    ++out_->seam_edges;
    out_->seam_sides.push_back(edge);
    return;
  }
  // Waits under its smaller vertex, in the entry of its face; the cell
  // across the face finds it there. (A face on the brick's boundary has
  // all its crossings shared: a seam edge, above.)
  const bool a_lower = a < b;
  const int slot = kSideSlots.slot[poly.edges[size_t(a_lower ? m : next)]][poly.faces[size_t(m)]];
  if (slot < 0) throw std::logic_error("contour: a polygon side off its cell face");
  int32_t& entry = out_->vertex_sides[4 * size_t(a_lower ? a : b) + size_t(slot)];
  const int32_t waiting = entry;
  if (waiting == -2) throw std::logic_error("contour: more than two cells share a polygon side");
  // NOTE: without a branch on whether the side is the first or the second
  // of its pair (either, as often): the pair is written in any case (add_fan
  // made room) and kept when it is one.
  uint32_t* pair = &out_->side_pairs[out_->pair_end];
  pair[0] = uint32_t(waiting);
  pair[1] = edge;
  out_->pair_end += waiting >= 0 ? 2 : 0;
  entry = waiting >= 0 ? -2 : int32_t(edge);
}

int32_t BrickContourer::add_centroid(const int32_t* ids, int n) {
  // Remark 3.9: the centroid of the polygon's points, in world space (the
  // affine map commutes with averaging), with their mean gradient.
  double p[3] = {0, 0, 0}, q[3] = {0, 0, 0};
  for (int m = 0; m < n; ++m)
    for (int a = 0; a < 3; ++a) {
      p[a] += out_->vertices[6 * size_t(ids[m]) + size_t(a)] / n;
      q[a] += out_->vertices[6 * size_t(ids[m]) + 3 + size_t(a)] / n;
    }
  return push_vertex(p, q);
}

namespace {

// Four times the squared area of the triangle (p, p + u, p + w).
double area2(const double* u, const double* w) {
  const double x = u[1] * w[2] - u[2] * w[1], y = u[2] * w[0] - u[0] * w[2], z = u[0] * w[1] - u[1] * w[0];
  return x * x + y * y + z * z;
}

}  // namespace

void BrickContourer::add_fan(const int32_t* ids, int n, const CellPolygon* poly) {
  const bool link = poly != nullptr;
  // NOTE: the apex whose smallest triangle is largest. Points on the edges
  // of one cell can be collinear (integer data at half-integer levels put
  // many at edge midpoints), and a fan from a fixed corner would then make
  // zero-area triangles; among the n fans at least one avoids them.
  int best = 0;
  if (n > 3) {
    // The points twice over, so that (apex + m) needs no wrap.
    double p[24][3];
    for (int m = 0; m < n; ++m)
      for (int a = 0; a < 3; ++a)
        p[m][a] = p[m + n][a] = double(out_->vertices[6 * size_t(ids[m]) + size_t(a)]);
    double best_area = -1;
    for (int apex = 0; apex < n; ++apex) {
      // The apex's smallest triangle. NOTE: every triangle, although the
      // apex cannot win once its smallest is no larger than the best's:
      // that early exit's branch went either way about as often.
      // Triangle (apex, m, m + 1) from the sides to m and m + 1; each side
      // serves two triangles and is computed once (the same differences).
      const double* o = p[apex];
      double smallest = HUGE_VAL;
      double u[3] = {p[apex + 1][0] - o[0], p[apex + 1][1] - o[1], p[apex + 1][2] - o[2]};
      for (int m = apex + 1; m + 1 < apex + n; ++m) {
        const double w[3] = {p[m + 1][0] - o[0], p[m + 1][1] - o[1], p[m + 1][2] - o[2]};
        smallest = std::min(smallest, area2(u, w));
        u[0] = w[0];
        u[1] = w[1];
        u[2] = w[2];
      }
      if (smallest > best_area) {
        best_area = smallest;
        best = apex;
      }
    }
  }
  // Appended one by one: a resize would zero them first, out of line.
  std::vector<int32_t>& tri = out_->triangles;
  const size_t at = tri.size();
  for (int m = best + 1; m + 1 < best + n; ++m) {
    tri.push_back(ids[best]);
    tri.push_back(ids[m < n ? m : m - n]);
    tri.push_back(ids[m + 1 < n ? m + 1 : m + 1 - n]);
  }
  // Consecutive triangles share the diagonal (apex, ids[m + 1]): edge 2 of
  // the one, edge 0 of the next; the polygon's sides are looked up. The
  // tetra method's fans are left to the lookup whole (link false).
  std::vector<uint8_t>& links = out_->fan_links;
  for (int m = 0; m + 3 < n; ++m) links.push_back(link ? fan_link(2, 0) : 0);
  links.push_back(0);
  if (link) {
    // Side (ids[best + r], ids[best + r + 1]): edge 0 of the first
    // triangle, edge 1 of triangle r - 1, edge 2 of the last; in this
    // order their edges increase.
    const uint32_t t0 = uint32_t(at / 3), last = t0 + uint32_t(n - 3);
    room_for_sides(n);
    for (int r = 0; r < n; ++r) {
      const uint32_t edge = r == 0 ? 3 * t0 : r == n - 1 ? 3 * last + 2 : 3 * (t0 + uint32_t(r - 1)) + 1;
      add_side(ids, *poly, best + r < n ? best + r : best + r - n, edge);
    }
  } else {
    const std::vector<uint8_t>& seam = out_->on_seam;
    for (const int32_t* t = &tri[at]; t != &tri[at] + 3 * size_t(n - 2); t += 3)
      out_->seam_edges += (seam[size_t(t[0])] & seam[size_t(t[1])]) + (seam[size_t(t[1])] & seam[size_t(t[2])]) +
                          (seam[size_t(t[2])] & seam[size_t(t[0])]);
  }
}

void BrickContourer::contour_cell_tetra(int i, int j, int k, const double g[8]) {
  for (int t = 0; t < 6; ++t) {
    const std::array<int, 4>& tet = tetrahedra()[t];
    int above = 0;
    for (int m = 0; m < 4; ++m) above |= (g[tet[m]] > 0) << m;
    const TetPolygon& poly = tet_polygon(t, above);
    if (poly.size == 0) continue;
    int32_t ids[4];
    for (int m = 0; m < poly.size; ++m) ids[m] = edge_vertex(i, j, k, poly.edges[m][0], poly.edges[m][1]);
    add_fan(ids, poly.size, nullptr);
  }
}

}  // namespace isoform

// One removal of Algorithm 5.1 (see removal.h).
#include "removal.h"

#include <algorithm>

#include <Eigen/Geometry>
#include <cmath>
#include <limits>

#include "half_plane.h"
#include "kernel.h"
#include "prefetch.h"
#include "weights.h"

namespace isoform::reduce {
namespace {

double cross_xy(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  return (b(0) - a(0)) * (c(1) - a(1)) - (b(1) - a(1)) * (c(0) - a(0));
}

// Is x on the segment a-b in the (x, y) projection (to rounding)?
bool on_segment_xy(const Eigen::Vector3d& x, const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  const Eigen::Vector2d ab(b(0) - a(0), b(1) - a(1)), ax(x(0) - a(0), x(1) - a(1));
  const double len2 = ab.squaredNorm();
  if (!(len2 > 0)) return ax.squaredNorm() == 0;
  const double cr = ab(0) * ax(1) - ab(1) * ax(0), t = ab.dot(ax) / len2;
  return std::abs(cr) <= 1e-9 * len2 && t >= -1e-9 && t <= 1 + 1e-9;
}

// The distance tracked: the tolerance, or without one an unbounded distance
// when the error is only to be measured.
double tracked_distance(const ReduceOptions& o) {
  if (o.tolerance > 0) return o.tolerance;
  return o.measure_error || (o.refine_point && !o.graph) ? std::numeric_limits<double>::infinity() : 0.0;
}

// The RMS tolerance tracked (graph mode only): the given one, or an
// unbounded one when the point is refined by the height errors.
double tracked_rms(const ReduceOptions& o) {
  if (!o.graph) return 0.0;
  if (o.graph_rms_tolerance > 0) return o.graph_rms_tolerance;
  return o.refine_point ? std::numeric_limits<double>::infinity() : 0.0;
}

}  // namespace

Remover::Remover(WorkMesh& w, const ReduceOptions& options)
    : w_(w), options_(options),
      tracker_(w, tracked_distance(options), tracked_rms(options), options.measure_error) {
  if (options.prevent_overlap) grid_ = std::make_unique<FaceGrid>(w);
}

// Theorem 5.3 with the point that will be inserted, not the centroid the
// theorem tests: for an open corona the origin of Section 5.2 (Figure 5.4)
// is a vertex or an edge's mid-point, and the refined and fallback points
// lie elsewhere again. The test: p's projection onto P lies strictly left
// of every directed edge of the platelet boundary polygon (5.17), and the
// polygon goes around it once (half_plane.h).
bool Remover::half_plane_ok(const Platelet& p, const Frame& frame, const Eigen::Vector3d& point) const {
  return half_plane_once(frame.uv(point), int(p.ring.size()), p.link_edges(),
                         [&](int j) { return frame.uv(w_.pos[size_t(p.ring[size_t(j)])]); });
}

// Graph mode: the removed boundary vertices of T lie on the two new boundary
// edges y_first-p and p-y_last in (x, y), so the domain stays covered.
bool Remover::domain_kept(const Platelet& p, const Eigen::Vector3d& point) const {
  const Eigen::Vector3d& first = w_.pos[size_t(p.ring.front())];
  const Eigen::Vector3d& last = w_.pos[size_t(p.ring.back())];
  for (int k = 0; k < 3; ++k) {
    if (!p.open_vertex[k]) continue;
    const Eigen::Vector3d& x = w_.pos[size_t(p.a[size_t(k)])];
    if (!on_segment_xy(x, first, point) && !on_segment_xy(x, point, last)) return false;
  }
  return true;
}

// isoform's guard: no new triangle is degenerate or turned over against the
// corona triangle it replaces (fan faces) or against T's plane (swapped
// faces); in graph mode every new triangle also keeps its (x, y) orientation.
bool Remover::faces_ok(const Proposal& q, const Frame& frame, const Eigen::Vector3d& point) const {
  const Platelet& p = q.platelet;
  const LocalFaces& faces = q.faces;
  for (size_t i = 0; i < faces.tri.size(); ++i) {
    const auto& t = faces.tri[i];
    const Eigen::Vector3d& x0 = local_pos(w_, p, point, t[0]);
    const Eigen::Vector3d& x1 = local_pos(w_, p, point, t[1]);
    const Eigen::Vector3d& x2 = local_pos(w_, p, point, t[2]);
    const Eigen::Vector3d nn = (x1 - x0).cross(x2 - x0);
    const double scale = std::max({(x1 - x0).squaredNorm(), (x2 - x1).squaredNorm(), (x0 - x2).squaredNorm()});
    if (!(nn.norm() > 1e-12 * scale)) return false;
    Eigen::Vector3d reference = frame.n;
    if (faces.source[i] >= 0) {
      const auto& o = w_.tri[size_t(faces.source[i])];
      reference = (w_.pos[size_t(o[1])] - w_.pos[size_t(o[0])]).cross(w_.pos[size_t(o[2])] - w_.pos[size_t(o[0])]);
    }
    if (!(nn.dot(reference) > 0)) return false;
    if (options_.graph && !(cross_xy(x0, x1, x2) > 1e-12 * scale)) return false;
  }
  return true;
}

// The point of the fitted height (along the frame's normal) above the
// kernel's point for the fitted one (kernel.h), the kernel pulled in by a
// twentieth of each edge so that no new triangle starts as a sliver; none
// when that kernel is empty.
std::optional<Eigen::Vector3d> Remover::kernel_candidate(const Platelet& p, const Frame& frame,
                                                         const Eigen::Vector3d& fitted) const {
  thread_local std::vector<Eigen::Vector2d> ring;
  ring.clear();
  for (int v : p.ring) ring.push_back(frame.uv(w_.pos[size_t(v)]));
  const std::optional<Eigen::Vector2d> c = kernel_point(ring, 0.05, frame.uv(fitted));
  if (!c) return std::nullopt;
  return Eigen::Vector3d(frame.c + (*c)(0) * frame.b1 + (*c)(1) * frame.b2 + (fitted - frame.c).dot(frame.n) * frame.n);
}

// The half-plane test, the fan and its guards for the fitted point; when it
// fails on a closed corona, beyond the seed, T's vertices (nearest to the
// fitted point first) are tried in its place, as an edge collapse would,
// and then the point above the polygon's kernel (kernel.h).
Outcome Remover::place_point(const Frame& frame, bool keep_xy, Proposal& q) const {
  const Platelet& p = q.platelet;
  Eigen::Vector3d candidates[5] = {q.point, w_.pos[size_t(p.a[0])], w_.pos[size_t(p.a[1])], w_.pos[size_t(p.a[2])],
                                   q.point};
  const Eigen::Vector3d fitted = q.point;
  std::sort(candidates + 1, candidates + 4, [&](const Eigen::Vector3d& x, const Eigen::Vector3d& y) {
    return (x - fitted).squaredNorm() < (y - fitted).squaredNorm();
  });
  const int count = p.closed && options_.vertex_fallback ? 5 : 1;
  Outcome first = Outcome::Removed;
  for (int i = 0; i < count; ++i) {
    if (i == 4) {
      const std::optional<Eigen::Vector3d> k = kernel_candidate(p, frame, fitted);
      if (!k) break;
      candidates[4] = *k;
    }
    Outcome o = Outcome::Removed;
    if (!half_plane_ok(p, frame, candidates[i]))
      o = Outcome::HalfPlane;
    else if (keep_xy && !domain_kept(p, candidates[i]))
      o = Outcome::Boundary;
    else {
      build_fan(p, q.faces);
      if (!faces_ok(q, frame, candidates[i])) o = Outcome::Flip;
    }
    if (o == Outcome::Removed) {
      q.point = candidates[i];
      q.at_vertex = i > 0 && i < 4;
      q.at_kernel = i == 4;
      return o;
    }
    if (i == 0) first = o;
  }
  return first;
}

void Remover::propose(int f, Proposal& out) const {
  out.face = f;
  out.swaps = 0;
  out.at_vertex = false;
  out.at_kernel = false;
  out.pending.assigned_valid = false;
  out.platelet.face = -1;
  out.platelet.faces.clear();
  out.platelet.ring.clear();
  out.region = out.changes = Box3f();
  out.outcome = evaluate(out);
  // What it read: T's vertices, and every vertex of the platelet's faces
  // (after a successful gather, the polygon).
  const Platelet& p = out.platelet;
  out.reads.assign(w_.tri[size_t(f)].begin(), w_.tri[size_t(f)].end());
  if (!p.ring.empty() && out.outcome != Outcome::Corona && out.outcome != Outcome::Nonmanifold) {
    out.reads.insert(out.reads.end(), p.ring.begin(), p.ring.end());
    return;
  }
  for (int g : p.faces) out.reads.insert(out.reads.end(), w_.tri[size_t(g)].begin(), w_.tri[size_t(g)].end());
}

// The tests of one removal that depend on its own neighbourhood alone.
Outcome Remover::evaluate(Proposal& q) const {
  const auto& t = w_.tri[size_t(q.face)];
  const bool touches_boundary = w_.boundary[size_t(t[0])] || w_.boundary[size_t(t[1])] || w_.boundary[size_t(t[2])];
  if (options_.lock_boundary && touches_boundary) return Outcome::Boundary;
  Platelet& platelet = q.platelet;
  const PlateletStatus status = gather_platelet(w_, q.face, platelet);
  if (status == PlateletStatus::Corona) return Outcome::Corona;
  if (status == PlateletStatus::Nonmanifold) return Outcome::Nonmanifold;
  // NOTE: what the fit, the tests and the commit read next, asked for
  // together (only timing depends on it; see speculate.cpp).
  tracker_.prefetch_lists(platelet);
  for (int v : platelet.ring) {
    prefetch(&w_.pos[size_t(v)]);
    prefetch(w_.vfaces.record(size_t(v)));
    prefetch(&w_.absolute[size_t(v)]);  // (the new faces' weights)
  }
  bool plane = false;
  const Frame frame = platelet_frame(w_, platelet, &plane);
  if (!plane) return Outcome::Flip;
  const bool keep_xy = options_.graph && !platelet.closed;
  q.fit = replacement_point(w_, platelet, frame, options_.point, keep_xy);
  if (!q.fit.ok || !q.fit.point.allFinite()) return Outcome::Flip;
  q.point = q.fit.point;
  const Outcome placed = place_point(frame, keep_xy, q);
  if (placed != Outcome::Removed) return placed;
  if (options_.swaps) {
    q.swaps = lawson_swaps(w_, platelet, frame, q.point, q.faces);
    if (q.swaps > 0 && !faces_ok(q, frame, q.point)) return Outcome::Flip;
  }
  if (options_.refine_point && tracker_.active()) {
    Eigen::Vector3d refined = q.point;
    const Eigen::Vector3d direction = options_.graph ? Eigen::Vector3d(0, 0, 1) : q.fit.normal;
    tracker_.refine(w_, platelet, frame, q.faces, direction, refined, q.pending);
    // Kept only when the moved point still passes every test.
    if (refined.allFinite() && half_plane_ok(platelet, frame, refined) && faces_ok(q, frame, refined)) q.point = refined;
  }
  for (int v : platelet.ring) prefetch(w_.vfaces.record(size_t(v)));
  if (tracker_.active() && !tracker_.measure(w_, platelet, q.point, q.faces, q.pending)) return Outcome::Tolerance;
  if (grid_) {
    const bool crosses = grid_->crosses(w_, platelet, q.point, q.faces, &q.region);
    q.changes = q.region;
    q.changes.add(grid_->boxes_of(platelet));
    if (crosses) return Outcome::Overlap;
  }
  new_weights(q);
  return Outcome::Removed;
}

// The weights of the new faces from the values the commit will leave (p at
// the point, with the fit's curvature): the same numbers update_weight
// would compute afterwards, computed here where removals run side by side.
void Remover::new_weights(Proposal& q) const {
  const int pv = q.platelet.a[0];
  const double absolute = std::abs(q.fit.k1) + std::abs(q.fit.k2);
  auto A = [&](int v) { return v == pv ? absolute : w_.absolute[size_t(v)]; };
  q.weights.clear();
  for (const auto& t : q.faces.tri) {
    const double sigma = angle_weight(local_pos(w_, q.platelet, q.point, t[0]), local_pos(w_, q.platelet, q.point, t[1]),
                                      local_pos(w_, q.platelet, q.point, t[2]));
    q.weights.push_back(triangle_weight(sigma, A(t[0]), A(t[1]), A(t[2])));
  }
}

Outcome Remover::accept(const Proposal& p) {
  if (p.outcome != Outcome::Removed) return p.outcome;
  if (tracker_.active()) {
    bool rms_stop = false, deferred = false;
    if (!tracker_.check(p.pending, &rms_stop, &deferred))
      return rms_stop ? Outcome::RmsStop : deferred ? Outcome::Deferred : Outcome::Tolerance;
    tracker_.accept(p.pending);
  }
  swaps_ += p.swaps;
  vertex_points_ += p.at_vertex ? 1 : 0;
  kernel_points_ += p.at_kernel ? 1 : 0;
  w_.live_faces -= (long long)(p.platelet.faces.size() - p.faces.tri.size());
  return Outcome::Removed;
}

// Replaces the platelet's faces by the new ones: p takes T's first vertex
// index (5.40), the other two vertices of T go, new faces reuse the lowest
// old ids (p.faces is sorted), and every changed face gets a new stamp and
// the current pass. It writes only the platelet's faces and vertices and the
// original vertices under those faces.
void Remover::commit(const Proposal& q, int pass) {
  const Platelet& p = q.platelet;
  const LocalFaces& faces = q.faces;
  const Replacement& r = q.fit;
  for (int f : p.faces)
    for (int v : w_.tri[size_t(f)]) {
      if (v == p.a[0] || v == p.a[1] || v == p.a[2]) continue;
      w_.vfaces.erase(size_t(v), f);
    }
  for (int v : p.a) w_.vfaces.clear(size_t(v));
  w_.vertex_alive[size_t(p.a[1])] = w_.vertex_alive[size_t(p.a[2])] = 0;
  for (size_t i = 0; i < p.faces.size(); ++i) {
    const size_t id = size_t(p.faces[i]);
    ++w_.face_stamp[id];
    if (i >= faces.tri.size()) {
      w_.face_alive[id] = 0;
      continue;
    }
    w_.tri[id] = faces.tri[i];
    w_.face_pass[id] = pass;
    for (int v : faces.tri[i]) w_.vfaces.push_back(size_t(v), int(id));
  }
  const size_t a = size_t(p.a[0]);
  w_.pos[a] = q.point;
  w_.boundary[a] = p.closed ? 0 : 1;
  w_.absolute[a] = std::abs(r.k1) + std::abs(r.k2);  // as new_weights took it
  w_.k1[a] = float(r.k1);
  w_.k2[a] = float(r.k2);
  w_.flags[a] = 0;
  for (int k = 0; k < 3; ++k) {
    w_.normal[3 * a + size_t(k)] = float(r.normal(k));
    w_.d1[3 * a + size_t(k)] = float(r.d1(k));
    w_.d2[3 * a + size_t(k)] = float(r.d2(k));
  }
  for (size_t i = 0; i < faces.tri.size(); ++i) w_.weight[size_t(p.faces[i])] = q.weights[i];
  if (tracker_.active()) tracker_.relink(p, q.pending, p.faces.data());
  if (grid_) grid_->update(w_, p, faces.tri.size());
}

}  // namespace isoform::reduce

// Error tracking of the tolerances (see tracker.h).
#include "tracker.h"

#include <algorithm>
#include <array>
#include <cstdint>

#include <Eigen/Geometry>
#include <cmath>
#include <limits>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>

namespace isoform::reduce {

// Closest point on a triangle by its Voronoi regions (vertices, edges, face).
double point_triangle_distance(const Eigen::Vector3d& x, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                               const Eigen::Vector3d& c) {
  const Eigen::Vector3d ab = b - a, ac = c - a, ax = x - a;
  const double d1 = ab.dot(ax), d2 = ac.dot(ax);
  if (d1 <= 0 && d2 <= 0) return ax.norm();
  const Eigen::Vector3d bx = x - b;
  const double d3 = ab.dot(bx), d4 = ac.dot(bx);
  if (d3 >= 0 && d4 <= d3) return bx.norm();
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return (x - (a + d1 / (d1 - d3) * ab)).norm();
  const Eigen::Vector3d cx = x - c;
  const double d5 = ab.dot(cx), d6 = ac.dot(cx);
  if (d6 >= 0 && d5 <= d6) return cx.norm();
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return (x - (a + d2 / (d2 - d6) * ac)).norm();
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0)
    return (x - (b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b))).norm();
  const double denom = va + vb + vc;
  if (!(std::abs(denom) > 0)) return std::min({ax.norm(), bx.norm(), cx.norm()});
  const double v = vb / denom, w = vc / denom;
  return (x - (a + ab * v + ac * w)).norm();
}

Tracker::Tracker(const WorkMesh& w, double distance_tolerance, double rms_tolerance, bool measure)
    : distance_(distance_tolerance), rms_(rms_tolerance), measure_(measure) {
  if (!active()) return;
  const size_t nv = w.pos.size(), nt = w.tri.size();
  original_.resize(nv);
  tbb::parallel_for(size_t(0), nv, [&](size_t v) { original_[v].x = w.pos[v]; });
  // The original triangles around each original vertex: for the distances
  // to the original surface (a finite tolerance, or a measurement).
  if ((distance_ > 0 && std::isfinite(distance_)) || measure_) {
    original_tri_ = w.tri;
    face_start_.assign(nv + 1, 0);
    for (size_t v = 0; v < nv; ++v) face_start_[v + 1] = face_start_[v] + int(w.vfaces[v].size());
    face_list_.resize(size_t(face_start_[nv]));
    tbb::parallel_for(size_t(0), nv, [&](size_t v) {
      std::copy(w.vfaces[v].begin(), w.vfaces[v].end(), face_list_.begin() + face_start_[v]);
    });
  }
  head_.assign(nt, -1);
  next_.assign(nv, -1);
  sampled_ = !std::isfinite(distance_) && !(rms_ > 0);
  if (sampled_ && measure_) follow_.assign(nv, -1);
  if (rms_ > 0) touched_.assign(nv, 0);
  for (size_t v = 0; v < nv; ++v) {
    if (w.vfaces[v].empty()) continue;
    const int f = w.vfaces[v].front();
    next_[v] = head_[size_t(f)];
    head_[size_t(f)] = int(v);
  }
}

double Tracker::rms() const { return original_.empty() ? 0.0 : std::sqrt(sum_err2_ / double(original_.size())); }

namespace {

// The height of triangle (a, b, c) above x's (x, y), and how far inside it
// x lies (its smallest barycentric coordinate in the xy projection).
double height_above(const Eigen::Vector3d& x, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                    const Eigen::Vector3d& c, double* inside) {
  const double det = (b(0) - a(0)) * (c(1) - a(1)) - (c(0) - a(0)) * (b(1) - a(1));
  if (!(std::abs(det) > 0)) {
    *inside = -std::numeric_limits<double>::infinity();
    return 0;
  }
  const double l1 = ((x(0) - a(0)) * (c(1) - a(1)) - (c(0) - a(0)) * (x(1) - a(1))) / det;
  const double l2 = ((b(0) - a(0)) * (x(1) - a(1)) - (x(0) - a(0)) * (b(1) - a(1))) / det;
  *inside = std::min({1 - l1 - l2, l1, l2});
  return (1 - l1 - l2) * a(2) + l1 * b(2) + l2 * c(2);
}

}  // namespace

bool Tracker::measure(const WorkMesh& w, const Platelet& p, const Eigen::Vector3d& point, const LocalFaces& faces,
                      TrackerPending& out) const {
  out.face.clear();
  out.err2.clear();
  out.delta.clear();
  out.largest_err2 = out.largest_distance = 0;
  out.fresh = 0;
  // Only a finite tolerance is checked per removal; a measurement without
  // one is made on the result (measure_result).
  const bool distances = distance_ > 0 && std::isfinite(distance_);
  // Without a bound or a measurement the faces refine() chose are all that
  // is needed, and it listed the vertices in the order of the walk below.
  if (out.assigned_valid && !(rms_ > 0) && !distances) {
    out.face.assign(out.assigned.begin(), out.assigned.end());
    out.assigned_valid = false;
    return true;
  }
  auto P = [&](int v) -> const Eigen::Vector3d& { return local_pos(w, p, point, v); };
  // The few original vertices nearest to the new point, whose triangles
  // bound its distance to the original surface.
  constexpr int kNear = 4;
  int near_vertex[kNear] = {-1, -1, -1, -1};
  double near_d2[kNear] = {1e300, 1e300, 1e300, 1e300};
  const bool reuse = out.assigned_valid;
  out.assigned_valid = false;
  // (After refine() the list is the one it walked.)
  if (!reuse) list_vertices(p, out.vertex);
  const size_t n = out.vertex.size();
  for (size_t index = 0; index < std::min(n, kRecordsAhead); ++index) prefetch(&original_[size_t(out.vertex[index])]);
  for (size_t index = 0; index < n; ++index) {
    if (index + kRecordsAhead < n) prefetch(&original_[size_t(out.vertex[index + kRecordsAhead])]);
    const int v = out.vertex[index];
    const Eigen::Vector3d& x = original_[size_t(v)].x;
    // Graph mode hands x to the new face above it, else to the nearest;
    // after refine() the face it chose is kept (in graph mode p's (x, y)
    // did not move, so it is the same face; else the distance to it is
    // still an upper bound of the distance to the reduced surface).
    int best = reuse ? out.assigned[index] : 0;
    double best_score = -std::numeric_limits<double>::infinity(), best_err2 = 0, nearest = 0;
    const size_t first = reuse ? size_t(out.assigned[index]) : 0, last = reuse ? first + 1 : faces.tri.size();
    // Without a bound or a measurement the kept face is all that is needed.
    const bool evaluate = rms_ > 0 || distances || !reuse;
    for (size_t i = first; evaluate && i < last; ++i) {
      const auto& t = faces.tri[i];
      double score = 0, err2 = 0, d = 0;
      if (rms_ > 0) {
        const double z = height_above(x, P(t[0]), P(t[1]), P(t[2]), &score);
        err2 = (x(2) - z) * (x(2) - z);
      } else {
        d = point_triangle_distance(x, P(t[0]), P(t[1]), P(t[2]));
        score = -d;
      }
      if (score > best_score) {
        best_score = score;
        best = int(i);
        best_err2 = err2;
        nearest = d;
      }
    }
    if (rms_ > 0 && distances) {
      nearest = std::numeric_limits<double>::infinity();
      for (const auto& t : faces.tri) nearest = std::min(nearest, point_triangle_distance(x, P(t[0]), P(t[1]), P(t[2])));
    }
    if (distances) {
      if (nearest > distance_) return false;
      out.largest_distance = std::max(out.largest_distance, nearest);
      double d2 = (x - point).squaredNorm();
      int id = v;
      for (int k = 0; k < kNear; ++k)
        if (d2 < near_d2[k]) {
          std::swap(d2, near_d2[k]);
          std::swap(id, near_vertex[k]);
        }
    }
    if (rms_ > 0) {
      out.delta.push_back(best_err2 - original_[size_t(v)].err2);
      out.err2.push_back(best_err2);
      out.largest_err2 = std::max(out.largest_err2, best_err2);
      out.fresh += touched_[size_t(v)] ? 0 : 1;
    }
    out.face.push_back(best);
  }
  // The new point against the original triangles around those vertices (a
  // subset of the original surface, so again an upper bound).
  double near_original = std::numeric_limits<double>::infinity();
  for (int v : near_vertex) {
    if (v < 0) continue;
    for (int k = face_start_[size_t(v)]; k < face_start_[size_t(v) + 1]; ++k) {
      const auto& t = original_tri_[size_t(face_list_[size_t(k)])];
      near_original = std::min(near_original, point_triangle_distance(point, original_[size_t(t[0])].x,
                                                                      original_[size_t(t[1])].x, original_[size_t(t[2])].x));
    }
  }
  if (distance_ > 0 && near_original < std::numeric_limits<double>::infinity()) {
    if (near_original > distance_) return false;
    out.largest_distance = std::max(out.largest_distance, near_original);
  }
  return true;
}

bool Tracker::check(const TrackerPending& t, bool* rms_stop, bool* deferred) {
  *rms_stop = false;
  *deferred = false;
  // NOTE: distances are >= 0, so this is the running maximum the removals
  // would leave, whatever the order of its terms.
  pending_max_ = std::max(max_distance_, t.largest_distance);
  // The guard: no knot of this removal farther than guard_ times the RMS of
  // the knots already moved off (their typical error so far).
  if (rms_ > 0 && guard_ > 0 && sum_err2_ > 0 && touched_count_ > 0 &&
      t.largest_err2 > guard_ * guard_ * (sum_err2_ / double(touched_count_))) {
    *deferred = true;
    return false;
  }
  // NOTE: the changes are added one by one, in the vertices' order, so the
  // sum is the same to the bit whenever the removal was computed.
  pending_sum_ = sum_err2_;
  for (double d : t.delta) pending_sum_ += d;
  if (rms_ > 0 && std::sqrt(std::max(0.0, pending_sum_) / double(original_.size())) > rms_) {
    *rms_stop = true;
    return false;
  }
  return true;
}

void Tracker::accept(const TrackerPending& t) {
  sum_err2_ = pending_sum_;
  touched_count_ += t.fresh;
  max_distance_ = pending_max_;
}

namespace {

// A vertex's rank among those handed to one face (a bijection of the ids:
// no two vertices share one).
uint32_t sample_rank(int v) { return uint32_t(v) * 2654435761u; }
// The vertex of a rank (2654435761 * 244002641 = 1 modulo 2^32).
int ranked_vertex(uint32_t rank) { return int(rank * 244002641u); }

}  // namespace

void Tracker::relink(const Platelet& p, const TrackerPending& t, const int* ids) {
  for (int f : p.faces) head_[size_t(f)] = -1;  // re-linked below
  if (sampled_) {
    relink_sample(p, t, ids);
    return;
  }
  for (size_t i = 0; i < t.vertex.size(); ++i) {
    const int v = t.vertex[i], f = ids[size_t(t.face[i])];
    next_[size_t(v)] = head_[size_t(f)];
    head_[size_t(f)] = v;
    if (rms_ > 0) {
      original_[size_t(v)].err2 = t.err2[i];
      touched_[size_t(v)] = 1;
    }
  }
}

void Tracker::relink_sample(const Platelet& p, const TrackerPending& t, const int* ids) {
  // Per new face, the least kSample ranks handed to it, ascending.
  static thread_local std::vector<std::array<uint32_t, kSample>> least;
  static thread_local std::vector<int> count;
  const size_t faces = p.faces.size();
  least.resize(faces);
  count.assign(faces, 0);
  for (size_t i = 0; i < t.vertex.size(); ++i) {
    const size_t f = size_t(t.face[i]);
    auto& l = least[f];
    const int n = std::min(count[f], kSample);
    uint32_t r = sample_rank(t.vertex[i]);
    if (n == kSample && r >= l[kSample - 1]) {
      ++count[f];
      continue;
    }
    int k = n == kSample ? kSample - 1 : n;
    for (; k > 0 && l[size_t(k - 1)] > r; --k) l[size_t(k)] = l[size_t(k - 1)];
    l[size_t(k)] = r;
    ++count[f];
  }
  // The kept ones linked in the order of t.vertex, as relink links all.
  for (size_t i = 0; i < t.vertex.size(); ++i) {
    const int v = t.vertex[i];
    const size_t local = size_t(t.face[i]);
    const int f = ids[local];
    const int n = std::min(count[local], kSample);
    if (sample_rank(v) <= least[local][size_t(n - 1)]) {
      next_[size_t(v)] = head_[size_t(f)];
      head_[size_t(f)] = v;
    } else if (!follow_.empty()) {
      // The kept one nearest to it.
      double best = std::numeric_limits<double>::infinity();
      for (int k = 0; k < n; ++k) {
        const int u = ranked_vertex(least[local][size_t(k)]);
        const double d2 = (original_[size_t(u)].x - original_[size_t(v)].x).squaredNorm();
        if (d2 < best) {
          best = d2;
          follow_[size_t(v)] = u;
        }
      }
    }
  }
}

namespace {

// The largest value of f(i) over [0, n), in parallel (max is exact, so the
// result does not depend on the split).
template <class F>
double largest(size_t n, F&& f) {
  return tbb::parallel_reduce(
      tbb::blocked_range<size_t>(0, n), 0.0,
      [&](const tbb::blocked_range<size_t>& r, double m) {
        for (size_t i = r.begin(); i != r.end(); ++i) m = std::max(m, f(i));
        return m;
      },
      [](double a, double b) { return std::max(a, b); });
}

}  // namespace

void Tracker::measure_result(const WorkMesh& w) {
  if (!measure_ || !(distance_ > 0) || std::isfinite(distance_)) return;
  // Each original vertex against the faces around the face it belongs to
  // (that face's, from where its removal put it, and those sharing a vertex
  // with it, where the surface nearest to it mostly is).
  const auto distance_to_face = [&](const Eigen::Vector3d& x, int f) {
    const auto& t = w.tri[size_t(f)];
    return point_triangle_distance(x, w.pos[size_t(t[0])], w.pos[size_t(t[1])], w.pos[size_t(t[2])]);
  };
  // x against face f and the faces sharing a vertex with it; the nearest
  // of them into *nearest.
  const auto around_face = [&](const Eigen::Vector3d& x, int f, int* nearest = nullptr) {
    double d = distance_to_face(x, f);
    if (nearest) *nearest = f;
    for (int corner : w.tri[size_t(f)])
      for (int g : w.vfaces[size_t(corner)]) {
        const double e = distance_to_face(x, g);
        if (e < d && nearest) *nearest = g;
        d = std::min(d, e);
      }
    return d;
  };
  const double from_original = largest(w.tri.size(), [&](size_t f) {
    double m = 0;
    if (!w.face_alive[f]) return m;
    for (int v = head_[f]; v >= 0; v = next_[size_t(v)]) m = std::max(m, around_face(original_[size_t(v)].x, int(f)));
    return m;
  });
  // The vertices left out of the lists (relink): each from the face of the
  // listed vertex its chain of followed ones ends at (the neighbourhood it
  // was handed to when it was left out, since moved on with the surface),
  // on to the nearest face around it while that is nearer. Any face gives
  // an upper bound.
  double from_left_out = 0;
  if (!follow_.empty()) {
    BigVector<int> owner(original_.size(), -1);
    tbb::parallel_for(size_t(0), w.tri.size(), [&](size_t f) {
      if (!w.face_alive[f]) return;
      for (int v = head_[f]; v >= 0; v = next_[size_t(v)]) owner[size_t(v)] = int(f);
    });
    from_left_out = largest(original_.size(), [&](size_t v) {
      int u = follow_[v];
      if (u < 0) return 0.0;
      while (follow_[size_t(u)] >= 0) u = follow_[size_t(u)];
      int f = owner[size_t(u)], g = f;
      if (f < 0) return 0.0;
      double d = around_face(original_[v].x, f, &g);
      while (g != f) {
        f = g;
        const double e = around_face(original_[v].x, f, &g);
        if (!(e < d)) break;
        d = e;
      }
      return d;
    });
  }
  // Each vertex against the original triangles around the few original
  // vertices nearest to it among those of its faces (a subset of the
  // original surface: again an upper bound).
  const double to_original = largest(w.pos.size(), [&](size_t p) {
    if (!w.vertex_alive[p] || w.vfaces[p].empty()) return 0.0;
    constexpr int kNear = 4;
    int near_vertex[kNear] = {-1, -1, -1, -1};
    double near_d2[kNear] = {1e300, 1e300, 1e300, 1e300};
    for (int f : w.vfaces[p])
      for (int v = head_[size_t(f)]; v >= 0; v = next_[size_t(v)]) {
        double d2 = (original_[size_t(v)].x - w.pos[p]).squaredNorm();
        int id = v;
        for (int k = 0; k < kNear; ++k)
          if (d2 < near_d2[k]) {
            std::swap(d2, near_d2[k]);
            std::swap(id, near_vertex[k]);
          }
      }
    double nearest = std::numeric_limits<double>::infinity();
    for (int v : near_vertex) {
      if (v < 0) continue;
      for (int k = face_start_[size_t(v)]; k < face_start_[size_t(v) + 1]; ++k) {
        const auto& t = original_tri_[size_t(face_list_[size_t(k)])];
        nearest = std::min(nearest, point_triangle_distance(w.pos[p], original_[size_t(t[0])].x,
                                                            original_[size_t(t[1])].x, original_[size_t(t[2])].x));
      }
    }
    return std::isfinite(nearest) ? nearest : 0.0;
  });
  max_distance_ = std::max({from_original, from_left_out, to_original});
}

}  // namespace isoform::reduce

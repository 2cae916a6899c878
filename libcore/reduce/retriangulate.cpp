// The fan (5.40) and the diagonal swaps (Definition 5.15).
#include "retriangulate.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <Eigen/Geometry>

#include "weights.h"

namespace isoform::reduce {
namespace {

double cross2(const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return a(0) * b(1) - a(1) * b(0); }

// Definition 5.15: the projected quadrilateral q0 q1 q2 q3 is strictly convex.
bool convex_projection(const Frame& f, const Eigen::Vector3d* q) {
  Eigen::Vector2d p[4];
  for (int i = 0; i < 4; ++i) p[i] = f.uv(q[i]);
  for (int i = 0; i < 4; ++i)
    if (!(cross2(p[(i + 1) % 4] - p[i], p[(i + 2) % 4] - p[(i + 1) % 4]) > 0)) return false;
  return true;
}

bool has_edge(const std::array<int, 3>& t, int a, int b) {
  for (int k = 0; k < 3; ++k)
    if ((t[size_t(k)] == a && t[size_t((k + 1) % 3)] == b) || (t[size_t(k)] == b && t[size_t((k + 1) % 3)] == a))
      return true;
  return false;
}

// Is a-b an edge of the mesh outside the platelet, or of the local faces?
bool edge_exists(const WorkMesh& w, const Platelet& p, const LocalFaces& faces, int a, int b) {
  for (const auto& t : faces.tri)
    if (has_edge(t, a, b)) return true;
  // NOTE: a face with both a and b is in both face lists; comparing the
  // lists' ids reads no triangle (a's faces beyond the platelet were not
  // read before and mostly missed the cache).
  const FaceLists::Span of_b = w.vfaces[size_t(b)];
  for (int f : w.vfaces[size_t(a)])
    for (int g : of_b)
      if (f == g && !in_platelet(p, f)) return true;
  return false;
}


// The angle weight (5.21) of each local face, computed when first asked for
// and kept until a swap replaces the face.
// NOTE: a quadrilateral's two faces were weighed again for every pair
// tried (some 13 convex pairs a removal on the bench's contour, with 2.6
// swaps); a face's weight is computed with its corners in the order they
// are stored, as the swap that makes it computes it.
struct FaceWeights {
  std::vector<double> value;  // NaN: not computed yet
  void reset(size_t n) { value.assign(n, std::numeric_limits<double>::quiet_NaN()); }
  template <class Pos>
  double of(const LocalFaces& faces, size_t i, Pos&& P) {
    if (std::isnan(value[i])) {
      const auto& t = faces.tri[i];
      value[i] = angle_weight(P(t[0]), P(t[1]), P(t[2]));
    }
    return value[i];
  }
};

// What try_swap found for a pair of faces.
enum class Swap { Done, Refused, NoEdgeLeft };

// Tries to swap the diagonal shared by faces i and j. Refused depends only
// on the two faces (no shared edge, not convex, not better); NoEdgeLeft
// (the new diagonal is an edge already) also on the others.
Swap try_swap(const WorkMesh& w, const Platelet& p, const Frame& frame, const Eigen::Vector3d& point,
              LocalFaces& faces, FaceWeights& sigma, size_t i, size_t j) {
  const auto& ti = faces.tri[i];
  const auto& tj = faces.tri[j];
  for (int k = 0; k < 3; ++k) {
    const int x = ti[size_t(k)], y = ti[size_t((k + 1) % 3)];
    for (int l = 0; l < 3; ++l) {
      if (tj[size_t(l)] != y || tj[size_t((l + 1) % 3)] != x) continue;
      const int o1 = ti[size_t((k + 2) % 3)], o2 = tj[size_t((l + 2) % 3)];
      if (o1 == o2) return Swap::Refused;
      auto P = [&](int v) -> const Eigen::Vector3d& { return local_pos(w, p, point, v); };
      const Eigen::Vector3d quad[4] = {P(x), P(o2), P(y), P(o1)};
      if (!convex_projection(frame, quad)) return Swap::Refused;
      const double before = std::min(sigma.of(faces, i, P), sigma.of(faces, j, P));
      const double new_i = angle_weight(P(o1), P(x), P(o2)), new_j = angle_weight(P(o2), P(y), P(o1));
      // NOTE: a margin, so that rounding cannot swap a diagonal back and forth.
      if (!(std::min(new_i, new_j) > before + 1e-12)) return Swap::Refused;
      if (edge_exists(w, p, faces, o1, o2)) return Swap::NoEdgeLeft;
      faces.tri[i] = {o1, x, o2};
      faces.tri[j] = {o2, y, o1};
      sigma.value[i] = new_i;
      sigma.value[j] = new_j;
      faces.source[i] = faces.source[j] = -1;
      return Swap::Done;
    }
  }
  return Swap::Refused;
}

}  // namespace

void build_fan(const Platelet& p, LocalFaces& out) {
  out.tri.clear();
  out.source.clear();
  const int n = int(p.ring.size());
  for (int j = 0; j < p.link_edges(); ++j) {
    out.tri.push_back({p.a[0], p.ring[size_t(j)], p.ring[size_t((j + 1) % n)]});
    out.source.push_back(p.ring_face[size_t(j)]);
  }
}

int lawson_swaps(const WorkMesh& w, const Platelet& p, const Frame& frame, const Eigen::Vector3d& point,
                 LocalFaces& faces) {
  int swaps = 0;
  // Each swap raises the sorted list of angle weights, so this ends; the cap
  // only guards against rounding.
  const size_t n = faces.tri.size();
  const int cap = 4 * int(n * n) + 8;
  // NOTE: after a swap the scan starts again, and most pairs are the same
  // two faces as before; a pair refused for what depends on the two faces
  // alone is not tried again until one of them changes. Each face carries
  // the number of the swap that last made it (0: the fan), each pair the
  // numbers it was refused with.
  static thread_local FaceWeights sigma;
  sigma.reset(n);
  static thread_local std::vector<int> made;
  static thread_local std::vector<std::array<int, 2>> refused;
  made.assign(n, 0);
  refused.assign(n * n, {-1, -1});
  bool changed = true;
  while (changed && swaps < cap) {
    changed = false;
    for (size_t i = 0; i < n && !changed; ++i)
      for (size_t j = i + 1; j < n && !changed; ++j) {
        std::array<int, 2>& seen = refused[i * n + j];
        if (seen[0] == made[i] && seen[1] == made[j]) continue;
        const Swap s = try_swap(w, p, frame, point, faces, sigma, i, j);
        if (s == Swap::Refused) seen = {made[i], made[j]};
        if (s != Swap::Done) continue;
        ++swaps;
        made[i] = made[j] = swaps;
        changed = true;
      }
  }
  return swaps;
}

}  // namespace isoform::reduce

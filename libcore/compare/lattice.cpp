#include "lattice.h"

namespace isoform::compare {

std::vector<LatticePoint> lattice(int k) {
  std::vector<LatticePoint> out;
  for (int j = 0; j <= k; ++j)
    for (int i = 0; i + j <= k; ++i) out.push_back({i, j, double(i) / k, double(j) / k});
  return out;
}

std::vector<int32_t> lattice_triangles(int k) {
  // Index of (i, j) in lattice(k): rows j hold k + 1 - j points.
  auto at = [k](int i, int j) { return int32_t(j * (k + 1) - j * (j - 1) / 2 + i); };
  std::vector<int32_t> t;
  for (int j = 0; j < k; ++j)
    for (int i = 0; i + j < k; ++i) {
      t.insert(t.end(), {at(i, j), at(i + 1, j), at(i, j + 1)});
      if (i + j + 1 < k) t.insert(t.end(), {at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  return t;
}

TessellationIds::TessellationIds(const Mesh& base, int k)
    : base_(base), k_(k), next_(int32_t(base.vertex_count())), corner_seen_(base.vertex_count(), false) {}

int32_t TessellationIds::id(size_t t, int i, int j, bool& fresh) {
  const int w[3] = {k_ - i - j, i, j};  // lattice weights of corners 0, 1, 2
  int zero = 0, corner = -1;
  for (int c = 0; c < 3; ++c) {
    if (w[c] == 0) ++zero;
    if (w[c] == k_) corner = c;
  }
  if (corner >= 0) {
    const int32_t v = base_.triangles[3 * t + size_t(corner)];
    fresh = !corner_seen_[size_t(v)];
    corner_seen_[size_t(v)] = true;
    return v;
  }
  if (zero == 1) {
    int a = 0;
    while (w[a] == 0 || w[(a + 1) % 3] == 0) ++a;  // the edge (a, a+1) holds the point
    int32_t va = base_.triangles[3 * t + size_t(a)], vb = base_.triangles[3 * t + size_t((a + 1) % 3)];
    int steps = w[(a + 1) % 3];  // from va toward vb
    if (va > vb) std::swap(va, vb), steps = k_ - steps;
    const uint64_t key = (uint64_t(va) * uint64_t(base_.vertex_count()) + uint64_t(vb)) * uint64_t(k_ + 1) + uint64_t(steps);
    auto [it, inserted] = edge_ids_.emplace(key, next_);
    fresh = inserted;
    if (inserted) ++next_;
    return it->second;
  }
  fresh = true;
  return next_++;
}

void edge_parameter(int e, double s, double& u, double& v) {
  double w[3] = {0.0, 0.0, 0.0};
  w[e] = 1.0 - s;
  w[(e + 1) % 3] = s;
  u = w[1];
  v = w[2];
}

}  // namespace isoform::compare

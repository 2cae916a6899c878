// The barycentric sample lattice of a base triangle and the tessellation it
// spans: lattice point (i, j) is (u, v) = (i/k, j/k); tessellation vertices
// on corners and edges are shared between neighbouring triangles, so the
// tessellation is watertight wherever the surface is continuous.
#pragma once

#include <cstdint>
#include <unordered_map>
#include <vector>

#include "libcore/mesh.h"

namespace isoform::compare {

struct LatticePoint {
  int i = 0, j = 0;
  double u = 0.0, v = 0.0;
};
// All points with i + j <= k, j outer, i inner.
std::vector<LatticePoint> lattice(int k);

// The k^2 triangles over the lattice of one triangle, as indices into
// lattice(k), oriented like the base triangle.
std::vector<int32_t> lattice_triangles(int k);

// Assigns tessellation vertex ids: base vertices keep theirs, edge points
// are shared by key, interior points are new.
class TessellationIds {
 public:
  TessellationIds(const Mesh& base, int k);
  // The id of lattice point (i, j) of triangle t, and whether it is new.
  int32_t id(size_t t, int i, int j, bool& fresh);
  int32_t count() const { return next_; }

 private:
  const Mesh& base_;
  int k_;
  int32_t next_;
  std::vector<bool> corner_seen_;
  std::unordered_map<uint64_t, int32_t> edge_ids_;
};

// The (u, v) at fraction s from corner e toward corner e+1 (mod 3).
void edge_parameter(int e, double s, double& u, double& v);

}  // namespace isoform::compare

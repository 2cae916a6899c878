// Each vertex's triangles (its star), as one table for the whole mesh: the
// neighbours (topology.h) and the reduction's manifold checks read it, and
// the reduction's working mesh fills its face lists from it, so the
// reduction builds it once.
#pragma once

#include <cstdint>
#include <vector>

#include "mesh.h"

namespace isoform {

struct VertexStars {
  std::vector<int64_t> start;  // per vertex, into faces; vertex_count() + 1 entries
  std::vector<int32_t> faces;  // each vertex's triangles, ascending

  size_t vertex_count() const { return start.empty() ? 0 : start.size() - 1; }
  const int32_t* begin(size_t v) const { return faces.data() + start[v]; }
  const int32_t* end(size_t v) const { return faces.data() + start[v + 1]; }
  size_t size(size_t v) const { return size_t(start[v + 1] - start[v]); }
};

// Every triangle index must name a vertex (validate_indices). Parallel (TBB).
VertexStars vertex_stars(const Mesh& mesh);

}  // namespace isoform

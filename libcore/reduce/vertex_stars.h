// Each vertex's triangles (its star), as one table for the whole mesh: the
// reduction's manifold checks read it, and the working mesh's face lists
// are filled from it, so it is built once.
#pragma once

#include <cstdint>
#include <vector>

#include "../mesh.h"

namespace isoform::reduce {

struct VertexStars {
  std::vector<int32_t> start;  // per vertex, into faces; vertex_count() + 1 entries
  std::vector<int32_t> faces;  // each vertex's triangles, ascending

  size_t vertex_count() const { return start.empty() ? 0 : start.size() - 1; }
  const int32_t* begin(size_t v) const { return faces.data() + start[v]; }
  const int32_t* end(size_t v) const { return faces.data() + start[v + 1]; }
  size_t size(size_t v) const { return size_t(start[v + 1] - start[v]); }
};

// Every triangle index must name a vertex (validate_indices). Parallel (TBB).
VertexStars vertex_stars(const Mesh& mesh);

}  // namespace isoform::reduce

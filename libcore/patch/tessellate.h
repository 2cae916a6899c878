// Triangles from a side-vertex surface: each base triangle split into 4^level
// triangles on the barycentric grid of 2^level steps per edge. Vertices on a
// mesh edge are computed once, from that edge's shared curve, and used by
// every triangle on the edge, so the tessellation is welded by construction:
// closed and manifold wherever the base mesh is.
#pragma once

#include "../mesh.h"
#include "../progress.h"
#include "side_vertex_surface.h"

namespace isoform::patch {

constexpr int kMaxTessellationLevel = 10;

struct TessellationStats {
  long long flat_samples = 0;  // samples where the surface was undefined: the flat triangle's point
  long long reversed_samples = 0; // interior samples whose exact normal points against the data normals
};

// Points (double and float), exact unit normals (the data normals at the
// vertices, the boundary normals n_S on edges, du x dv inside, turned to the
// side of the triangle's data normals), triangles in the base triangles'
// winding, neighbours and parts. Throws InvalidArgument for a level outside
// 0..kMaxTessellationLevel or a result too large for int32 indices,
// Cancelled when progress asks to stop. Parallel (TBB); the same result for
// any thread count.
Mesh tessellate(const SideVertexSurface& surface, int level, const Progress& progress,
                TessellationStats* stats = nullptr);

}  // namespace isoform::patch

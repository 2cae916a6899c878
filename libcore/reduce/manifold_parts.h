// The reduction's option manifold_parts_only: the input's parts (triangles
// joined by shared edges, a non-manifold edge joining all of its triangles)
// that pass every entry check (validate.h) are reduced, the others are copied
// unchanged. A violation marks the parts of the triangles it involves: an
// edge's part, both parts of an overlapping pair, every part around a
// non-manifold or non-finite vertex. An index naming no vertex still refuses
// the whole mesh.
#pragma once

#include "reduce.h"

namespace isoform::reduce {

// reduce_mesh with options.manifold_parts_only. keep_fraction applies to the
// triangles of the reducible parts. When every part passes this is the plain
// reduction; otherwise the result holds the reduced parts' vertices and
// triangles first, then those of the parts left alone, unchanged (their
// curvature the input's, or 0 flagged kCurvatureFailed when it had none).
// Isolated vertices are dropped, as by the plain reduction. With
// keep_fraction 1, or no reducible part, the mesh is left as it is.
ReduceStats reduce_manifold_parts(Mesh& mesh, const ReduceOptions& options, const Progress& progress);

}  // namespace isoform::reduce

// The vertex-to-triangle table (see vertex_stars.h).
#include "vertex_stars.h"

#include "stretch_sort.h"

namespace isoform {

// NOTE: sorted in stretches side by side (stretch_sort.h): each vertex's
// triangles ascending, as one scan of the triangles would list them.
VertexStars vertex_stars(const Mesh& mesh) {
  VertexStars stars;
  sort_by_keys_in_stretches(
      mesh.triangle_count(), mesh.vertex_count(),
      [&](size_t t, auto visit) {
        for (int k = 0; k < 3; ++k) visit(size_t(mesh.triangles[3 * t + size_t(k)]));
      },
      stars.start, stars.faces);
  return stars;
}

}  // namespace isoform

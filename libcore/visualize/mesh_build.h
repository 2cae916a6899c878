// Small steps shared by the Chapter 2 meshes: appending one mesh to another,
// the two triangles of a grid cell (Section 2.3's I1 and I2), and vertex
// normals from the triangles around each vertex.
#pragma once

#include <array>

#include "../mesh.h"
#include "../volume.h"

namespace isoform::visualize {

// Appends part's vertices (points, colours, normals when both have them),
// triangles, edges and parts to into, with indices shifted.
void append_mesh(Mesh& into, const Mesh& part);

// Adds a vertex at p (world) with colour rgba.
void add_vertex(Mesh& mesh, const Vec3d& p, const std::array<uint8_t, 4>& rgba);

// The triangles of an nu x nv vertex grid whose vertex (i, j) is first +
// j * nu + i: ((i,j),(i+1,j),(i+1,j+1)) and ((i,j),(i+1,j+1),(i,j+1)) per cell,
// or the reverse orientation when flip.
void add_grid_triangles(Mesh& mesh, int32_t first, int nu, int nv, bool flip);

// The curve network of such a grid: segments along u, then along v.
void add_grid_edges(Mesh& mesh, int32_t first, int nu, int nv);

// normals = unit area-weighted sums of the triangles' normals at each
// vertex; `fallback` where a vertex has only degenerate triangles or none.
void compute_vertex_normals(Mesh& mesh, const Vec3d& fallback);

}  // namespace isoform::visualize

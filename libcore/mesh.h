// The seed's tables for a triangulated surface (Section 3.3): the vertex
// table V, the triangle table T, the neighbour table, the part of each
// triangle, and the normal table N. Plain arrays, so that the C API can copy
// them out and OpenMesh can be built from them in O(n) when needed.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "curvature/vertex_curvature.h"

namespace isoform {

struct MeshStats {
  long long boundary_edges = 0;
  long long nonmanifold_edges = 0;
  long long inconsistent_edges = 0;
  long long degenerate_triangles = 0;
  long long euler_characteristic = 0;
};

// What the contour met on its way (zero for meshes not made by a contour).
struct ContourStats {
  double isovalue = 0.0;
  bool isovalue_was_auto = false;
  long long ambiguous_faces = 0;
  long long degenerate_saddles = 0;
  long long extra_points = 0;
  long long centroid_points = 0;
  long long near_sample_points = 0;  // crossings held 1/1000 edge from a sample
};

struct Mesh {
  std::vector<float> points;      // 3 per vertex, world coordinates
  // Optional: the same points in double precision, when the caller had them
  // (analytic test surfaces). Curvature fits use them when present: float
  // coordinates alone limit curvature to about 1e-7 / h^2 for edge length h.
  std::vector<double> precise_points;
  std::vector<float> normals;     // 3 per vertex, unit length
  std::vector<int32_t> triangles; // 3 vertex indices per triangle
  std::vector<int32_t> neighbours;// 3 per triangle: across edge (v_i, v_i+1), -1 if none
  std::vector<int32_t> parts;     // 1 per triangle, 0 = largest part
  // Optional, empty by default (the PLY writer adds what is present):
  std::vector<uint8_t> colors;    // 4 per vertex: red, green, blue, alpha (0..255)
  std::vector<int32_t> edges;     // 2 vertex indices per loose line segment
  int32_t part_count = 0;
  MeshStats stats;
  ContourStats contour;
  VertexCurvature curvature;      // empty until Chapter 4 has run (curvature/)

  size_t vertex_count() const { return points.size() / 3; }
  size_t triangle_count() const { return triangles.size() / 3; }
  size_t edge_count() const { return edges.size() / 2; }
};

}  // namespace isoform

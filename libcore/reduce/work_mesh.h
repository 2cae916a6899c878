// The working structure of the reduction: a face table with per-vertex
// face lists, alive flags and per-face stamps (for the lazy queue), and the
// per-vertex data the reduction carries (absolute curvature for the weights,
// curvature and normals for the result).
//
// NOTE: not OpenMesh. Removing a triangle is a contraction of three vertices
// into one with a local re-triangulation that is computed and checked before
// anything changes (docs/reduce.md). With a face table and vertex face lists
// that is a direct edit of a few dozen entries; in OpenMesh it is two edge
// collapses whose own preconditions differ from the corona conditions, plus
// flips and a garbage collection.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "../mesh.h"
#include "big_vector.h"
#include "face_lists.h"
#include "../vertex_stars.h"

namespace isoform::reduce {

struct WorkMesh {
  // (The arrays the removals read all over: big_vector.h.)
  BigVector<Eigen::Vector3d> pos;
  BigVector<std::array<int, 3>> tri;
  BigVector<uint8_t> face_alive;
  BigVector<uint32_t> face_stamp;  // changes whenever the face does
  BigVector<int> face_pass;        // the pass that made the face (0: input)
  BigVector<double> weight;        // ω (5.23), set when the face is made (queue.h)
  FaceLists vfaces;  // per vertex: the faces around it
  BigVector<uint8_t> vertex_alive, boundary;
  // Per vertex: absolute curvature |k1| + |k2| (the weights), and the rest
  // of the curvature and the normal for the result.
  BigVector<double> absolute;
  std::vector<float> k1, k2, normal, d1, d2;
  std::vector<uint8_t> flags;
  long long live_faces = 0;

  int face_with_vertex_index(int f, int v) const {
    const auto& t = tri[size_t(f)];
    return t[0] == v ? 0 : t[1] == v ? 1 : t[2] == v ? 2 : -1;
  }
};

// Builds the structure from a validated mesh that carries normals, with the
// curvature of its vertices, its star table (vertex_stars.h) and the flags
// of its boundary vertices as validate_manifold gave them (computed here
// when empty); precise points are used when present.
WorkMesh build_work_mesh(const Mesh& mesh, const VertexCurvature& curvature, const VertexStars& stars,
                         const std::vector<uint8_t>& on_boundary);

// The mesh of the surviving vertices (in their order) and faces, with
// normals, curvature (its stats: `curvature_stats` for the new count of
// vertices) and precise points when `precise`; neighbours, parts and stats
// computed.
Mesh write_back(const WorkMesh& work, bool precise, const CurvatureStats& curvature_stats,
                const ContourStats& contour);

}  // namespace isoform::reduce

// Closest points on triangle meshes, for the reduction benchmark's
// Metro-style error: the distance from a point to one triangle, and an
// axis-aligned bounding-volume hierarchy over a mesh that answers "how far
// is the nearest point of the mesh" exactly (the same answer as trying every
// triangle, in logarithmic time on surface meshes).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace isoform_reduce_bench {

using Vec3 = std::array<double, 3>;

// Squared distance from p to the triangle (a, b, c), degenerate ones
// (repeated or collinear corners) included.
double point_triangle_distance2(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c);

// A mesh as flat arrays: 3 coordinates per vertex, 3 vertex indices per triangle.
struct MeshView {
  const double* points = nullptr;
  size_t vertex_count = 0;
  const int32_t* triangles = nullptr;
  size_t triangle_count = 0;
};

class TriangleTree {
 public:
  // Copies the triangles' corners; the view may go away afterwards. An empty
  // mesh gives a tree whose every distance is infinite.
  explicit TriangleTree(const MeshView& mesh);

  // Squared distance from p to the nearest point of the mesh; with nearest,
  // also the input index of a triangle at that distance (-1 if none).
  double distance2(const Vec3& p, int32_t* nearest = nullptr) const;

  size_t triangle_count() const { return corners_.size() / 9; }

 private:
  struct Node {
    double lo[3], hi[3];
    uint32_t first;  // leaf: first triangle; inner: the right child (left is the next node)
    uint32_t count;  // triangles in a leaf, 0 for an inner node
  };
  uint32_t build(std::vector<uint32_t>& order, const std::vector<double>& centroids, uint32_t begin,
                 uint32_t end);

  std::vector<Node> nodes_;
  std::vector<double> corners_;  // 9 per triangle, in leaf order
  std::vector<uint32_t> input_index_;  // of each triangle in leaf order
};

}  // namespace isoform_reduce_bench

// Contouring one brick: the cells whose lower corner lies in the brick become
// triangles over a brick-local vertex table. Vertices on edges that cells of
// other bricks also use carry a global key, so that merge.h can share them.
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include "../mesh.h"
#include "../volume.h"
#include "brick_store.h"

namespace isoform {

enum class ContourMethod { Cells = 0, Tetra = 1 };

// A brick's tables while it is being contoured.
struct BrickWork {
  // Per vertex: the point (world coordinates), then the gradient (world
  // space, not normalised).
  std::vector<float> vertices;
  std::vector<int32_t> triangles;   // brick-local vertex indices
  std::vector<uint8_t> fan_links;   // per triangle: FanLink (below)
  std::vector<uint8_t> on_seam;     // per vertex: 1 when other bricks may use it
  uint32_t seam_edges = 0;          // BrickMesh::seam_count
  // The cell method's polygon sides (BrickSides): triangle edges as written;
  // the pairs are side_pairs[0, pair_end), the rest is room.
  std::vector<uint32_t> side_pairs, lone_sides, seam_sides;
  size_t pair_end = 0;
  // Per vertex, 4 entries: a side from it (as its smaller vertex) on each of
  // the 4 cell faces around its grid edge, waiting for the same side of the
  // cell across: its edge, -1 (none) or -2 (paired).
  std::vector<int32_t> vertex_sides;
  std::vector<std::pair<uint64_t, int32_t>> shared;  // (edge key, local vertex)
  ContourStats stats;
};

// What a brick's cells met (ContourStats, per brick).
struct BrickCounts {
  int32_t ambiguous_faces = 0, degenerate_saddles = 0, extra_points = 0, centroid_points = 0,
          near_sample_points = 0;
};

// Triangles t and t + 1 of one fan in one cell share an edge that no other
// triangle uses (the cell method: a diagonal from the fan's apex, or a spoke
// to its extra point; inside a polygon with at most one segment per face no
// two non-adjacent points share a cell face, and the extra point is the
// polygon's own). fan_links[t] records it: 0 when t and t + 1 share no such
// edge, else kFanLinked | (edge of t) | (edge of t + 1) << 2, edge i being
// (v_i, v_i+1) of the triangle as the contour wrote it. brick_topology.h
// links these pairs without looking them up.
constexpr uint8_t kFanLinked = 0x80;
inline uint8_t fan_link(int edge_here, int edge_next) { return uint8_t(kFanLinked | edge_here | (edge_next << 2)); }

// The cell method knows, for every triangle edge that no fan link covers,
// where its other triangle is: such an edge is a side of its cell's polygon
// on a cell face, and the same side of the polygon in the cell across that
// face (or, for a fan around an extra point, the spoke to the polygon's
// first point, shared by the fan's first and last triangles). So the
// contour pairs them as it goes, and brick_topology.h needs no lookup.
// Edges are numbered 3 t + i, edge i being (v_i, v_i+1) of triangle t as the
// contour wrote it.
struct BrickSides {
  const uint32_t* pairs = nullptr;  // two edges per pair
  const uint32_t* lone = nullptr;   // sides whose cell across the face was not contoured
  // Edges with both ends shared (SeamEdge records), in increasing order of
  // their triangles; seam_count of them (BrickMesh).
  const uint32_t* seam = nullptr;
  uint32_t pair_count = 0, lone_count = 0;
  bool known = false;  // false: the tetra method, whose edges are looked up
};

// A contoured brick's tables, kept in BrickStores (brick_store.h) until
// they are merged.
struct BrickMesh {
  const float* vertices = nullptr;  // per vertex: point (3), then gradient (3)
  const int32_t* triangles = nullptr;
  const uint8_t* fan_links = nullptr;  // per triangle (BrickWork::fan_links)
  const std::pair<uint64_t, int32_t>* shared = nullptr;
  uint32_t vertex_count = 0, triangle_count = 0, shared_count = 0;
  // Triangle edges with both ends shared that no fan link covers: the
  // brick's SeamEdge records (brick_topology.h).
  uint32_t seam_count = 0;
  BrickSides sides;
  BrickCounts counts;
};

struct CellPolygon;  // cell_polygons.h

// Per-thread scratch for contouring bricks of one grid at one level.
class BrickContourer {
 public:
  BrickContourer(const Affine& index_to_world, double isovalue, ContourMethod method);
  // Contours the brick into out, its tables copied into store; leaves out
  // empty and returns false when no cell of the brick crosses.
  bool run(const Brick& brick, BrickMesh& out, BrickStores& store);

 private:
  // Fills the row masks (and g_ if needed); false when no cell can cross.
  bool prepare(const Brick& brick);
  double moved(int i, int j, int k) const;
  const Vec3d& gradient(int i, int j, int k);
  int32_t edge_vertex(int ci, int cj, int ck, int p, int q);
  int32_t add_vertex(const Vec3d& index_pos, const Vec3d& grad);
  // Appends a vertex (world point, world gradient) as floats; its index.
  int32_t push_vertex(const double* point, const double* grad);
  int32_t add_centroid(const int32_t* ids, int n);
  // Appends the fan of polygon ids[0, n); poly: the cell polygon whose
  // points they are (cell method: sides paired), or null (tetra method:
  // every edge left to the lookup).
  void add_fan(const int32_t* ids, int n, const CellPolygon* poly);
  // Side m of poly (from ids[m] to ids[m + 1]), written as triangle edge
  // `edge`: a seam edge, or paired with the same side of the cell across.
  void add_side(const int32_t* ids, const CellPolygon& poly, int m, uint32_t edge);
  // Room for the pairs of n more sides and a spoke in side_pairs.
  void room_for_sides(int n);
  void contour_cell_trilinear(int i, int j, int k, const double g[8], int above);
  void contour_cell_tetra(int i, int j, int k, const double g[8]);
  void gather(int i, int j, int k, double g[8]) const;

  Affine xform_;
  double cofactor_[3][3];  // of xform_'s linear part (Affine::apply_normal)
  double normal_sign_;     // the sign of its determinant
  double iso_;
  float iso_above_, iso_float_;  // the isovalue as float thresholds (constructor)
  ContourMethod method_;
  int slots_;
  const Brick* brick_ = nullptr;
  BrickWork* out_ = nullptr;     // work_ while a brick is contoured
  BrickWork work_;               // grows to the largest brick, then is reused
  bool all_defined_ = true;
  Index3 n_{0, 0, 0};            // corner samples per axis: cells + 1
  // Moved f - iso at the corner samples, kept only when some sample moved
  // (moved_samples_); else g_at() reads f - iso from the brick.
  std::vector<double> g_;
  bool moved_samples_ = false;
  double g_at(int i, int j, int k) const;
  // Per row of corner samples (j, k), bit i: g > 0 (above_), undefined
  // (undefined_). Rows are at most 64 samples long (run() checks).
  std::vector<uint64_t> above_, undefined_;
  std::vector<Vec3d> grad_;      // Zucker-Hummel gradients, lazily
  bool four_gradients_ = false;  // has_zucker_hummel_four() (gradient.h)
  std::vector<uint8_t> has_grad_;
  std::vector<int32_t> slot_vertex_;  // per corner sample and slot: vertex or -1
};

// The global key of a vertex on the slot-th edge of sample (x, y, z):
// slots 0-2 are the axis edges, 3-5 the face diagonals normal to each axis,
// 6 the cell diagonal (tetra method). Throws Unsupported outside +-2^19.
uint64_t edge_key(int x, int y, int z, int slot);

}  // namespace isoform

// Beyond the seed: a removal must not make the surface cross itself. The
// seed's tests and isoform's other guards look only at the platelet; where
// two sheets of a surface lie closer than the triangles grow (thin bone in a
// CT contour), a new triangle can pass through a triangle of the other
// sheet. FaceGrid keeps every current face in the cells of a uniform grid
// that its box meets, so that a removal's new faces are tested against the
// faces near them (triangle_overlap.h, the input check's narrow phase) before
// anything changes.
//
// NOTE: a pair is tested in one cell only, the one holding the low corner
// of the intersection of the two boxes (as the input check does), so a face
// met in several cells is tested once without a set of the faces seen.
// Boxes are kept in float, rounded outwards: a box is only a filter, and the
// exact test decides.
// NOTE: a face far larger than the cells (a ground quad under a detailed
// model, or faces grown between refits) would fill thousands of cells: a
// face whose box meets more than `big_cells` (512) cells is kept out of them,
// with its box, in a list that every query reads, and a query whose region meets more cells
// than the table has slots reads the slots instead of walking its cells. The
// grid is fitted again when the list outgrows twice its length at the last
// fit (plus 64 and a 64th of the faces).
#pragma once

#include <array>
#include <atomic>
#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "big_vector.h"
#include "retriangulate.h"
#include "work_mesh.h"

namespace isoform::reduce {

struct Box3f {
  std::array<float, 3> lo{1, 1, 1}, hi{0, 0, 0};  // empty when lo > hi
  bool empty() const { return lo[0] > hi[0]; }
  bool meets(const Box3f& b) const {
    for (int k = 0; k < 3; ++k)
      if (lo[size_t(k)] > b.hi[size_t(k)] || b.lo[size_t(k)] > hi[size_t(k)]) return false;
    return true;
  }
  void add(const Box3f& b);
};

// The box of a triangle, rounded outwards to float.
Box3f triangle_box(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c);

class FaceGrid {
 public:
  // Every live face of w, in cells of about its faces' mean size; faces
  // meeting more than big_cells cells in the list of big ones.
  explicit FaceGrid(const WorkMesh& w, size_t big_cells = 512);
  FaceGrid(const FaceGrid&) = delete;
  FaceGrid& operator=(const FaceGrid&) = delete;

  // Would one of `faces` (p.a[0] at `point`) cross a current face that is not
  // one of p's? *region: the union of the new faces' boxes (what was read).
  bool crosses(const WorkMesh& w, const Platelet& p, const Eigen::Vector3d& point, const LocalFaces& faces,
               Box3f* region) const;
  // The union of the boxes of p's faces as they are now.
  Box3f boxes_of(const Platelet& p) const;
  // After a commit of p's removal: its faces' old entries go, the new ones
  // (the first `made` of p.faces, as the commit wrote them) come. Commits
  // may call it side by side.
  void update(const WorkMesh& w, const Platelet& p, size_t made);
  // Starts again with cells fitted to the faces as they are now when they
  // have grown to 4 times their area (faces only grow) or the big ones have
  // become too many. Only between batches: no query may run beside it.
  void refit(const WorkMesh& w);
  // Faces kept out of the cells now, and fits so far (tests, statistics).
  size_t big_faces() const { return big_.size(); }
  int fits() const { return fits_; }

 private:
  // NOTE: the table holds the cells' faces itself, with their boxes, up to 4
  // in a slot of two cache lines; a cell with more takes further slots of the same key.
  // Slots are never emptied (a cell keeps its key), so a probe ends at the
  // first slot never used.
  static constexpr int kPerSlot = 4;
  struct alignas(128) Slot {
    uint64_t key = kFree;
    int32_t count = 0;
    int32_t face[kPerSlot];
    Box3f box[kPerSlot];
  };
  static constexpr uint64_t kFree = ~uint64_t(0);

  void build(const WorkMesh& w, double cell);
  std::array<int, 3> cell_of(const float x[3]) const;
  static uint64_t key(int x, int y, int z);
  size_t first_slot(uint64_t key) const;
  void set_shift();
  void insert(int face, const Box3f& b);
  void erase(int face, const Box3f& b);
  void add(uint64_t key, int face, const Box3f& box);
  void grow();
  bool is_big(const std::array<int, 3>& c0, const std::array<int, 3>& c1) const;
  // Calls test(face, box) once for every face in the cells whose box meets
  // region (big faces apart); true as soon as a call returns true.
  template <class Test>
  bool any_in_cells(const Box3f& region, Test test) const;

  double inverse_ = 1;
  Eigen::Vector3d origin_{0, 0, 0};
  long long built_faces_ = 0;
  BigVector<Box3f> box_;  // per face id: its box when inserted
  BigVector<Slot> slots_;
  size_t used_ = 0;
  size_t big_cells_ = 512;
  struct Big {
    int face;
    Box3f box;
  };
  std::vector<Big> big_;      // faces kept out of the cells, with their boxes
  std::vector<int32_t> big_at_;  // per face id: its place in big_, or -1 (sized at the first)
  size_t big_limit_ = 64;     // refit beyond this many
  int fits_ = 0;
  int shift_ = 54;  // 64 - log2(the slots)
  std::atomic_flag lock_ = ATOMIC_FLAG_INIT;  // update() side by side
};

}  // namespace isoform::reduce

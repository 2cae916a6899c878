// One step of Algorithm 5.1 of Hamann (1991): the tests that decide whether
// a triangle can go (corona, half-plane test of Theorem 5.3 on the point
// actually inserted, boundary lock of Remark 5.8, and isoform's guards), and
// the removal itself: the replacement point, the fan, the swaps, the commit.
#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "face_grid.h"
#include "platelet.h"
#include "reduce.h"
#include "retriangulate.h"
#include "tracker.h"

namespace isoform::reduce {

enum class Outcome { Removed, Corona, HalfPlane, Flip, Nonmanifold, Boundary, Overlap, Tolerance, RmsStop, Deferred };

// The removal of one triangle as computed against the mesh as it is, before
// anything changes: what the tests that depend on its own neighbourhood
// found and, when they all pass, what would change.
struct Proposal {
  int face = -1;
  Outcome outcome = Outcome::Removed;  // Removed: every local test passed
  Platelet platelet;
  LocalFaces faces;
  Replacement fit;
  Eigen::Vector3d point{0, 0, 0};  // the point inserted
  int swaps = 0;
  bool at_vertex = false;  // the point is a vertex of T (vertex fallback)
  bool at_kernel = false;  // the point lies above the polygon's kernel (the same)
  TrackerPending pending;
  std::vector<double> weights;  // ω (5.23) of each new face, as update_weight gives it after the commit
  // The vertices whose data it read: T's, and those of every platelet face.
  std::vector<int> reads;
  // With the overlap guard (face_grid.h), once it ran: the boxes its test
  // read (the new faces'), and those a commit would change (the old and the
  // new faces'); empty otherwise.
  Box3f region, changes;
  // A refusal remembered from the last pass (speculate.h): only face,
  // outcome and reads are set.
  bool recalled = false;
};

class Remover {
 public:
  Remover(WorkMesh& w, const ReduceOptions& options);
  // Computes the removal of face f into `out`, changing nothing (so several
  // may run side by side).
  void propose(int f, Proposal& out) const;
  // Decides a proposal computed against the mesh as it is now: the
  // tracker's checks that depend on every removal so far. Removed: it is
  // counted (the live faces, the tracker's sums) and must be committed
  // before anything reads its platelet again.
  Outcome accept(const Proposal& p);
  // Makes an accepted removal's changes, its new faces belonging to `pass`.
  // Removals whose platelets share no vertex may be committed side by side.
  void commit(const Proposal& p, int pass);
  long long swaps() const { return swaps_; }
  long long vertex_points() const { return vertex_points_; }
  long long kernel_points() const { return kernel_points_; }
  const Tracker& tracker() const { return tracker_; }
  // The overlap guard's grid fitted again to the faces when they have
  // outgrown it (between batches: nothing is computed ahead then).
  void refit_grid() {
    if (grid_) grid_->refit(w_);
  }
  Tracker& tracker() { return tracker_; }

 private:
  Outcome evaluate(Proposal& p) const;
  Outcome place_point(const Frame& frame, bool keep_xy, Proposal& p) const;
  std::optional<Eigen::Vector3d> kernel_candidate(const Platelet& p, const Frame& frame, const Eigen::Vector3d& fitted) const;
  bool half_plane_ok(const Platelet& p, const Frame& frame, const Eigen::Vector3d& point) const;
  bool domain_kept(const Platelet& p, const Eigen::Vector3d& point) const;
  bool faces_ok(const Proposal& p, const Frame& frame, const Eigen::Vector3d& point) const;
  void new_weights(Proposal& p) const;

  WorkMesh& w_;
  ReduceOptions options_;
  Tracker tracker_;
  std::unique_ptr<FaceGrid> grid_;  // prevent_overlap
  long long swaps_ = 0, vertex_points_ = 0, kernel_points_ = 0;
};

}  // namespace isoform::reduce

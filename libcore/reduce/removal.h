// One step of Algorithm 5.1 of Hamann (1991): the tests that decide whether
// a triangle can go (corona, half-plane test of Theorem 5.3 on the point
// actually inserted, boundary lock of Remark 5.8, and isoform's guards), and
// the removal itself: the replacement point, the fan, the swaps, the commit.
#pragma once

#include <vector>

#include "platelet.h"
#include "reduce.h"
#include "retriangulate.h"
#include "tracker.h"

namespace isoform::reduce {

enum class Outcome { Removed, Corona, HalfPlane, Flip, Nonmanifold, Boundary, Tolerance, RmsStop, Deferred };

class Remover {
 public:
  Remover(WorkMesh& w, const ReduceOptions& options);
  // Tries to remove face f; on success the faces it makes belong to `pass`.
  Outcome try_remove(int f, int pass);
  long long swaps() const { return swaps_; }
  long long vertex_points() const { return vertex_points_; }
  const Tracker& tracker() const { return tracker_; }
  Tracker& tracker() { return tracker_; }

 private:
  Outcome place_point(const Frame& frame, bool keep_xy, Eigen::Vector3d& point, bool* at_vertex);
  bool half_plane_ok(const Frame& frame, const Eigen::Vector3d& point) const;
  bool domain_kept(const Eigen::Vector3d& point) const;
  bool faces_ok(const Frame& frame, const Eigen::Vector3d& point) const;
  void commit(const Replacement& r, const Eigen::Vector3d& point, int pass);

  WorkMesh& w_;
  ReduceOptions options_;
  Tracker tracker_;
  Platelet platelet_;
  LocalFaces faces_;
  std::vector<int> ids_;
  long long swaps_ = 0, vertex_points_ = 0;
};

}  // namespace isoform::reduce

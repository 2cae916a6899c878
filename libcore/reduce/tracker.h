// Error tracking for the reduction's tolerances. Every original vertex is
// assigned to one current triangle; when a removal replaces triangles, their
// vertices are handed to the nearest new triangle (without a tolerance, a
// sample of them: relink). That gives, per removal and before anything
// changes:
// - distance mode (any surface): each original vertex's distance to its
//   triangle (an upper bound of its distance to the reduced surface), and the
//   new point's distance to the original triangles around the same original
//   vertices, so both directions are bounded at vertices (docs/reduce.md);
// - graph mode: the height error at each original knot of the triangle above
//   it, summed over all knots for the RMS of (5.41) (Remark 5.10).
#pragma once

#include <vector>

#include <Eigen/Core>

#include "assign.h"
#include "big_vector.h"
#include "prefetch.h"
#include "retriangulate.h"

namespace isoform::reduce {

// A new face's unit normal and the length of its edges' cross product (0:
// degenerate), computed once per face for every vertex handed to it.
struct FaceNormal {
  Eigen::Vector3d n{0, 0, 0};
  double length = 0;
};

// What Tracker::refine and Tracker::measure find for one removal, before
// anything changes: computing it reads the tracker without changing it, so
// that removals can be computed side by side (speculate.h).
struct TrackerPending {
  std::vector<int> vertex, face;         // each original vertex and the new face it goes to
  std::vector<double> err2, delta;       // graph: its squared height error, and the change of the sum
  double largest_err2 = 0;               // graph: the largest err2
  double largest_distance = 0;           // the largest tracked distance (distances measured)
  long long fresh = 0;                   // graph: vertices whose error is computed the first time
  std::vector<int> assigned;             // the faces refine() handed the vertices to
  bool assigned_valid = false;           // refine() ran for this removal
  std::vector<ProjectedFace> projected;  // refine's scratch
  std::vector<FaceNormal> face_normals;  // refine's scratch
};

class Tracker {
 public:
  // Call on the input, before any removal. An infinite distance tolerance
  // tracks the assignment only (for refine); `measure` also computes the
  // tracked distances then (for max_distance).
  Tracker(const WorkMesh& w, double distance_tolerance, double rms_tolerance, bool measure);
  // NOTE: with an infinite distance tolerance, `measure` asks for
  // measure_result at the end; no removal computes distances then.
  bool active() const { return distance_ > 0 || rms_ > 0; }
  // Asks for the first original vertex of each platelet face early (see
  // refine): only timing depends on it.
  void prefetch_lists(const Platelet& p) const {
    if (!active()) return;
    for (int f : p.faces) prefetch(&head_[size_t(f)]);
  }

  // Moves the new point along `direction` (unit) to the least-squares best
  // place for the original vertices under the platelet's faces, one
  // Gauss-Newton step on their distances to the new faces (graph mode: their
  // height errors, exactly). Each vertex goes to the new face above it
  // (graph), the nearest (finite distance tolerance) or the one its
  // projection onto T's plane (frame) falls in (assign.h). Beyond the seed: its point lies on the fitted
  // surface, and a piecewise linear surface through points on a curved
  // surface is on one side of it.
  void refine(const WorkMesh& w, const Platelet& p, const Frame& frame, const LocalFaces& faces,
              const Eigen::Vector3d& direction, Eigen::Vector3d& point, TrackerPending& out) const;

  // The removal whose old faces are p.faces and new faces `faces` with p at
  // `point`, as far as it depends on its own vertices: their new faces and
  // errors into `out`. False when the distance tolerance would be exceeded.
  bool measure(const WorkMesh& w, const Platelet& p, const Eigen::Vector3d& point, const LocalFaces& faces,
               TrackerPending& out) const;
  // The rest, which depends on every removal made so far: false when the
  // RMS tolerance would be exceeded (*rms_stop; Remark 5.10: the reduction
  // stops) or the guard refuses (*deferred; set_guard).
  bool check(const TrackerPending& t, bool* rms_stop, bool* deferred);
  // Graph mode, beyond the seed: refuse a removal that would take one of its
  // knots farther than `factor` times the RMS height error of the knots
  // moved off so far (0: off). The caller relaxes it when a pass stalls.
  void set_guard(double factor) { guard_ = factor; }
  double guard() const { return guard_; }
  // Takes the last successful check's sums as the tracker's: call right
  // after it, in the removals' order.
  void accept(const TrackerPending& t);
  // Hands the original vertices of the removal of p's faces to their new
  // faces (ids[i] is the face id given to faces[i]). Removals whose
  // platelets share no face may be relinked side by side.
  // Without a tolerance (the point refined, or the error measured at the
  // end) a new face keeps at most kSample of the vertices handed to it: the
  // kSample of least rank (a fixed scramble of their ids). Each one left
  // out follows the kept one nearest to it, for measure_result.
  // NOTE: the refined point is one least-squares step along one direction;
  // a few vertices under each of the platelet's faces determine it as well
  // as all of them, but late in a reduction to 1 % each face holds about 50,
  // and walking them all would be a large part of every removal's work.
  // A contour reduced with the sample keeps the error it had without it
  // (docs/reduce.md, "Beyond the seed").
  void relink(const Platelet& p, const TrackerPending& t, const int* ids);
  static constexpr int kSample = 4;
  // The original vertices listed under face f now.
  std::vector<int> listed(int f) const {
    std::vector<int> out;
    for (int v = head_[size_t(f)]; v >= 0; v = next_[size_t(v)]) out.push_back(v);
    return out;
  }

  // Without a distance tolerance but asked to measure: the largest distance
  // of the result, bounded from above at the end rather than per removal
  // (each original vertex's distance to the face it belongs to, or for one
  // left out of the lists the face of the vertex it follows, and each
  // vertex's distance to the original triangles around the original
  // vertices nearest to it among those of its faces) into max_distance().
  // Call once, after the last removal.
  void measure_result(const WorkMesh& w);
  double max_distance() const { return max_distance_; }
  double rms() const;

 private:
  // The original vertices of p's faces, face by face, each list in its
  // order, into `out`.
  // NOTE: the walk reads only the links (4 bytes a vertex); the records
  // (32 bytes, all over memory) are then read in that order, each asked
  // for kRecordsAhead vertices early.
  void list_vertices(const Platelet& p, std::vector<int>& out) const {
    out.clear();
    for (int f : p.faces)
      for (int v = head_[size_t(f)]; v >= 0; v = next_[size_t(v)]) out.push_back(v);
  }
  static constexpr size_t kRecordsAhead = 8;
  // relink when sampled_.
  void relink_sample(const Platelet& p, const TrackerPending& t, const int* ids);

  double distance_, rms_;
  bool measure_;
  // NOTE: an original vertex's point and squared height error side by side,
  // one record of 32 bytes: the lists are walked in the queue's order, and
  // check() read the error from a second array, a cache miss of its own.
  struct alignas(32) Original {
    Eigen::Vector3d x;
    double err2 = 0;  // squared height error (graph mode)
  };
  // (big_vector.h)
  BigVector<Original> original_;
  BigVector<int> face_start_, face_list_;  // original vertex -> original faces (CSR)
  BigVector<std::array<int, 3>> original_tri_;
  BigVector<int> head_, next_;  // current face -> its original vertices (linked)
  bool sampled_ = false;        // at most kSample vertices a face (relink)
  BigVector<int> follow_;       // sampled and measured: per vertex left out, the vertex it follows (else -1)
  double sum_err2_ = 0, max_distance_ = 0;
  std::vector<uint8_t> touched_;  // per original vertex: its error was ever computed (graph mode)
  long long touched_count_ = 0;
  double guard_ = 0;
  double pending_sum_ = 0, pending_max_ = 0;  // of the last check
};

double point_triangle_distance(const Eigen::Vector3d& x, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                               const Eigen::Vector3d& c);

}  // namespace isoform::reduce

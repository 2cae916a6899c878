// Algorithm 5.1 of Hamann (1991): triangle reduction by iterative triangle
// removal, in passes: Remark 5.9's "new" triangles, which may go only when
// no "old" one can, read as passes (a reduction that ignores the remark
// ends with an error an order of magnitude larger). A pass takes the
// triangles that exist when it starts ("old") in increasing weight and
// tries each once; triangles made during the pass ("new") wait for the
// next pass.
// The queue is lazy (queue.h): a pass orders (weight, id, stamp) once, and an
// entry whose face has changed since (stamp) or was made in this pass is skipped.
//
// NOTE: ties of the weight (many on regular grids, all on a plane) are
// broken by the face id, lower first; ids are those of the input's triangle
// table, and a new face takes the lowest id of the faces it replaces, so the
// order is deterministic and does not depend on the platform's sort.
#include "reduce.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <exception>
#include <optional>

#include <Eigen/Geometry>
#include <cmath>
#include <tuple>

#include <tbb/task_arena.h>
#include <tbb/task_group.h>

#include "../curvature/surface_curvature.h"
#include "../errors.h"
#include "../mesh_normals.h"
#include "graph_embedding.h"
#include "manifold_parts.h"
#include "queue.h"
#include "removal.h"
#include "speculate.h"
#include "validate.h"
#include "work_mesh.h"

namespace isoform {
namespace {

using reduce::Outcome;
using reduce::WorkMesh;

void check_options(const ReduceOptions& o) {
  if (!(o.keep_fraction > 0 && o.keep_fraction <= 1))
    throw InvalidArgument("reduce: keep_fraction must be in (0, 1], not " + std::to_string(o.keep_fraction));
  if (!(o.tolerance >= 0) || !std::isfinite(o.tolerance))
    throw InvalidArgument("reduce: tolerance must be a finite distance >= 0 (0 = off)");
  if (!(o.graph_rms_tolerance >= 0) || !std::isfinite(o.graph_rms_tolerance))
    throw InvalidArgument("reduce: graph_rms_tolerance must be finite and >= 0 (0 = off)");
  if (o.graph_rms_tolerance > 0 && !o.graph)
    throw InvalidArgument("reduce: graph_rms_tolerance needs graph mode (a mesh z = f(x, y))");
}


// The self-overlap check (validate.h) as a task beside the whole reduction,
// which works on a copy until it succeeds.
// NOTE: the check only reads the input and is a small part of a
// reduction's CPU time; the reduction has serial stretches (the manifold
// checks' edge table, the working mesh's face lists, the queue, each batch's
// decisions) in which the other core would idle. The reduction runs
// isolated (tbb::this_task_arena::isolate), so a thread waiting for its own
// parallel work never picks up a piece of the check (a batch would wait for
// it); an idle thread does. Beside the whole reduction rather than beside
// the preparation only, the check fills more of those idle stretches.
// A bad input is still refused by name: failed() stops the passes, and the
// check's error is thrown when the reduction is done or fails.
class OverlapCheck {
 public:
  OverlapCheck() = default;
  // Starts the check (once).
  void start(const Mesh& mesh) {
    group_.run([this, &mesh] {
      try {
        reduce::validate_no_overlap(mesh, "reduce");
      } catch (...) {
        error_ = std::current_exception();
        failed_.store(true, std::memory_order_release);
      }
    });
  }
  OverlapCheck(const OverlapCheck&) = delete;
  OverlapCheck& operator=(const OverlapCheck&) = delete;
  ~OverlapCheck() { wait(); }
  void wait() { group_.wait(); }
  // Has the check found an overlap (or failed) so far?
  bool failed() const { return failed_.load(std::memory_order_acquire); }
  // Waits for the check; throws its error.
  void finish() {
    wait();
    if (error_) std::rethrow_exception(error_);
  }

 private:
  std::exception_ptr error_;
  std::atomic<bool> failed_{false};
  tbb::task_group group_;
};

// Thrown by the passes when the overlap check has failed: the reduction
// stops, and the check's error is reported instead.
struct OverlapFound {};

// The working mesh of an input that passed the manifold checks (validate.h),
// with the input's normals and curvature, or computed ones; the stats of the
// curvature into *curvature_stats.
// NOTE: the input is read where it is, not copied first (60 MB for a
// 1M-triangle mesh with double points): only a mesh without normals is.
WorkMesh prepared_work_mesh(const Mesh& mesh, const VertexStars& stars, const std::vector<uint8_t>& on_boundary,
                            const Progress& progress, bool* computed, CurvatureStats* curvature_stats) {
  const Mesh* source = &mesh;
  Mesh with_normals;
  if (mesh.normals.size() != mesh.points.size()) {
    with_normals.points = mesh.points;
    with_normals.precise_points = mesh.precise_points;
    with_normals.triangles = mesh.triangles;
    estimate_normals(with_normals);
    source = &with_normals;
  }
  *computed = mesh.curvature.k1.size() != mesh.vertex_count();
  // NOTE: the weights need |k1| + |k2| at every vertex (5.22), and the
  // result carries the curvature: the cubic fit over the two-ring, cheaper
  // than `isoform curvature`'s quartic default over the three-ring, with the
  // reduction's errors no worse (docs/reduce.md, "Decisions the dissertation
  // leaves open" and the Table 5.1 block).
  VertexCurvature fitted;
  if (*computed) {
    CurvatureOptions fit;
    fit.method = CurvatureMethod::Cubic;
    compute_curvature(*source, fit, progress, fitted, nullptr);
  }
  const VertexCurvature& curvature = *computed ? fitted : mesh.curvature;
  *curvature_stats = curvature.stats;
  progress.stage(ISOFORM_STAGE_REDUCE);
  return reduce::build_work_mesh(*source, curvature, stars, on_boundary);
}

void count_refusal(Outcome o, ReduceRefusals& r) {
  switch (o) {
    case Outcome::Corona: ++r.corona; break;
    case Outcome::HalfPlane: ++r.half_plane; break;
    case Outcome::Flip: ++r.flip; break;
    case Outcome::Nonmanifold: ++r.nonmanifold; break;
    case Outcome::Boundary: ++r.boundary; break;
    case Outcome::Overlap: ++r.overlap; break;
    case Outcome::Tolerance:
    case Outcome::Deferred:
    case Outcome::RmsStop: ++r.tolerance; break;
    case Outcome::Removed: break;
  }
}

// Entries of a pass computed ahead at a time (speculate.h): enough to keep
// the threads busy between two serial stretches, few enough that a removal
// rarely meets an earlier one of its batch.
constexpr size_t kBatch = 128;
// How far ahead of the removal being applied its successors' data is asked for.
constexpr size_t kApplyAhead = 3;

// The passes of Remark 5.9 until the target count, a tolerance stop, or a
// pass that removes nothing (Remark 5.11).
void run_passes(WorkMesh& w, const ReduceOptions& options, long long target, const Progress& progress,
                const OverlapCheck& overlap, ReduceStats& stats) {
  reduce::Remover remover(w, options);
  reduce::PassQueue queue;
  // A batch's accepted removals computed ahead, in the order accepted, and
  // their commit, a crew item (declared before the crew: while an exception
  // leaves, the crew waits for the items it was given).
  std::array<const reduce::Proposal*, kBatch> pending{};
  size_t accepted = 0, handed = 0;  // of pending: accepted, handed to the crew
  bool committing = false;          // the crew's stretch is the batch's commits
  int pass = 0;
  const auto commit = [&](size_t k) { remover.commit(*pending[k], pass); };
  // (Both stopped before the measurement at the end, which is parallel.)
  std::optional<reduce::BatchCrew> crew(std::in_place);
  std::optional<reduce::Speculation> speculation(std::in_place, w.pos.size(), w.tri.size(),
                                                       options.remember_refusals, *crew);
  reduce::Speculation& ahead = *speculation;
  // Beyond the seed (graph mode): a removal that would take one of its knots
  // past 4 times the RMS error of the knots moved so far waits (docs/reduce.md).
  if (options.graph) remover.tracker().set_guard(4.0);
  const long long start = w.live_faces;
  long long tries = 0;
  stats.stop_reason = 0;
  // NOTE: a batch's removals are decided one at a time in the queue's order
  // (accept: the counts and the tracker's sums) and their changes made
  // by the crew (commit), side by side: removals of one batch that are both
  // accepted share no platelet vertex (the second read none that the first
  // changed, speculate.h), so their commits write disjoint data. An entry
  // whose reads an accepted removal changed waits for the commits first.
  // NOTE: where the queue's order visits neighbours one after another (ties
  // of the weight, as on flat regions, are taken in face order, and
  // neighbouring faces have near ids), most removals computed ahead read
  // what an earlier one of their batch changed and are computed again, one
  // by one: the work ahead is lost. A batch in which a quarter of the
  // entries met an earlier removal so is followed by one computed one
  // removal at a time, each against the mesh with every earlier removal
  // made, which also counts how many would have met one; fewer, and the
  // next batch is computed ahead again. Either way each removal is computed
  // against the mesh it would meet one at a time: the same result.
  bool ahead_pays = true;
  while (w.live_faces > target) {
    pass = ++stats.passes;
    remover.refit_grid();
    long long removed = 0, deferred = 0;
    bool stop = false, reached = false;
    // NOTE: the helpers commit the batch's accepted removals while this
    // thread decides the next entries (batch_crew.h, open()): the decisions
    // read only what the commits do not write (an entry whose reads an
    // accepted removal changed waits for every commit first, below), and
    // the commits of accepted removals write disjoint data. Nothing may
    // change the mesh while a removal is being computed: the commits start
    // once all of the batch's computations are done.
    const auto hand_over = [&] {
      if (!committing) {
        if (!crew->all_done()) return;  // (handed over at the next acceptance, or below)
        crew->open(commit);
        committing = true;
      }
      for (; handed < accepted; ++handed) crew->add();
    };
    // Every accepted removal committed (and every computation ahead done).
    const auto commit_pending = [&] {
      if (!committing) {
        ahead.settle();
        if (accepted == 0) return;
      }
      hand_over();
      crew->drain();
    };
    // (Isolated: waiting for its parallel work, this thread takes none of
    // the crew's helpers.)
    const std::vector<reduce::QueueEntry>* pass_order = nullptr;
    tbb::this_task_arena::isolate([&] { pass_order = &queue.next_pass(w, pass); });
    const std::vector<reduce::QueueEntry>& order = *pass_order;
    for (size_t begin = 0; begin < order.size() && !stop && !reached; begin += kBatch) {
      const size_t end = std::min(order.size(), begin + kBatch);
      const bool speculate = ahead_pays && options.compute_ahead;
      if (speculate)
        ahead.propose(remover, w, order, begin, end, pass);
      else
        ahead.begin_serial(w, order, begin, end, pass);
      size_t met = 0;  // entries that read what an earlier removal of the batch changed
      for (size_t i = begin; i < end; ++i) {
        ahead.prefetch(w, i + kApplyAhead);
        const reduce::QueueEntry& e = order[i];
        if (w.live_faces <= target) {
          reached = true;
          break;
        }
        const size_t f = size_t(e.face);
        if (!ahead.was_current(i)) continue;
        if (ahead.read_changed(i)) {
          ++met;
          commit_pending();
        }
        if (!w.face_alive[f] || w.face_stamp[f] != e.stamp || w.face_pass[f] == pass) {
          met += speculate ? 0 : 1;  // an earlier removal of the batch changed its face
          continue;
        }
        if ((++tries & 1023) == 0) {
          if (progress.cancelled()) throw Cancelled("reduce: cancelled");
          if (overlap.failed()) throw OverlapFound{};
          progress.fraction(float(double(start - w.live_faces) / double(std::max(1LL, start - target))));
        }
        const reduce::Proposal& proposal = ahead.current(remover, i);
        if (!speculate && ahead.read_changed(i)) ++met;
        const Outcome o = remover.accept(proposal);
        if (o == Outcome::Removed) {
          ahead.applied(proposal);
          if (speculate) {
            pending[accepted++] = &proposal;
            hand_over();
          } else
            remover.commit(proposal, pass);
          ++removed;
          ++stats.removals;
          continue;
        }
        count_refusal(o, stats.refused);
        stats.refusals_remembered += proposal.recalled ? 1 : 0;
        if (o != Outcome::Tolerance && o != Outcome::Deferred && o != Outcome::RmsStop && o != Outcome::Overlap)
          ahead.refused(i);
        deferred += o == Outcome::Deferred ? 1 : 0;
        if (o == Outcome::RmsStop) {
          stop = true;
          break;
        }
      }
      commit_pending();
      accepted = handed = 0;
      committing = false;
      ahead_pays = 4 * met < end - begin;
      remover.refit_grid();  // (nothing is computed ahead between batches)
    }
    if (stop) {
      stats.stop_reason = 3;
      break;
    }
    if (removed == 0 && deferred > 0) {  // the guard stalls the reduction: relax it
      remover.tracker().set_guard(2 * remover.tracker().guard());
      continue;
    }
    if (removed == 0) {
      stats.stop_reason = options.tolerance > 0 && stats.refused.tolerance > 0 ? 2 : 1;
      break;
    }
  }
  speculation.reset();
  crew.reset();
  stats.swaps = remover.swaps();
  stats.vertex_points = remover.vertex_points();
  stats.kernel_points = remover.kernel_points();
  remover.tracker().measure_result(w);
  stats.max_distance = remover.tracker().max_distance();
  stats.graph_rms = remover.tracker().rms();
}

}  // namespace

ReduceStats reduce_mesh(Mesh& mesh, const ReduceOptions& options, const Progress& progress) {
  check_options(options);
  // NOTE: the passes ask every few hundred removals, so a small mesh could
  // be reduced whole under a flag set before the call; asked here, and
  // again before the passes and before the result replaces the mesh.
  if (progress.cancelled()) throw Cancelled("reduce: cancelled");
  if (options.manifold_parts_only) return reduce::reduce_manifold_parts(mesh, options, progress);
  ReduceStats stats;
  stats.triangles_before = stats.triangles_after = (long long)mesh.triangle_count();
  stats.vertices_before = stats.vertices_after = (long long)mesh.vertex_count();
  if (options.keep_fraction >= 1.0 || mesh.triangle_count() == 0) {
    reduce::validate_input(mesh, "reduce");
    if (options.graph) reduce::validate_graph(mesh, "reduce");
    if (progress.cancelled()) throw Cancelled("reduce: cancelled");
    return stats;  // an unchanged copy
  }
  // The manifold checks' error first, else the overlap check's, else any other.
  reduce::validate_indices(mesh, "reduce");
  // A graph (every triangle counterclockwise seen from +z) whose (x, y)
  // projection is proved one-to-one cannot overlap itself
  // (graph_embedding.h); the proof reads the star table, so the general
  // check of a graph starts only when the proof fails.
  OverlapCheck overlap;
  if (!options.graph) overlap.start(mesh);
  VertexStars stars;
  std::vector<uint8_t> on_boundary;  // per vertex, from the manifold check
  WorkMesh w;
  CurvatureStats curvature_stats;
  bool one_to_one = false;
  try {
    tbb::this_task_arena::isolate([&] {
      stars = vertex_stars(mesh);
      reduce::validate_manifold(mesh, stars, "reduce", &on_boundary);
      if (options.graph) {
        reduce::validate_graph(mesh, "reduce");
        one_to_one = reduce::projects_one_to_one(mesh, stars);
      }
    });
  } catch (...) {
    overlap.wait();  // (the check reads the mesh)
    throw;
  }
  if (options.graph && !one_to_one) overlap.start(mesh);
  try {
    tbb::this_task_arena::isolate([&] {
      w = prepared_work_mesh(mesh, stars, on_boundary, progress, &stats.curvature_computed, &curvature_stats);
      const long long target = (long long)std::ceil(options.keep_fraction * double(mesh.triangle_count()) - 1e-9);
      run_passes(w, options, target, progress, overlap, stats);
    });
  } catch (...) {
    overlap.finish();
    throw;
  }
  overlap.finish();
  if (progress.cancelled()) throw Cancelled("reduce: cancelled");
  const bool precise = mesh.precise_points.size() == mesh.points.size();
  mesh = reduce::write_back(w, precise, curvature_stats, mesh.contour);
  stats.triangles_after = (long long)mesh.triangle_count();
  stats.vertices_after = (long long)mesh.vertex_count();
  return stats;
}

}  // namespace isoform

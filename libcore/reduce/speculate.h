// The removals of a pass computed ahead, side by side (Algorithm 5.1 with
// the passes of Remark 5.9, as in reduce.cpp): the next entries of the
// pass's order have their removals computed in parallel against the mesh as
// it is; the pass then applies them one at a time in the queue's order, and
// recomputes one when an earlier removal of the batch changed what it read.
//
// NOTE: the result is the serial one to the bit, at any thread count. A
// pass's order is fixed when it starts (its new faces wait for the next
// one), so the entries ahead are known. A removal's computation
// (Remover::propose) reads T's vertices, their face lists, the faces in them
// and their tracked original vertices, and the polygon's points and face
// lists; a removal that goes changes only faces with all their vertices in
// its platelet (T and the polygon) and only those vertices' data. So a
// computation none of whose vertices (T's and its polygon's, or every vertex
// of its faces when the platelet failed) an earlier removal of the batch
// changed reads what it would read now, and gives what it would give now.
// What depends on every removal so far (the tracker's RMS and guard, the
// target count) is decided when the removal is applied (Remover::apply).
//
// Beyond that, a pass remembers the removals it refused for their own
// neighbourhood (corona, half-plane, flip, non-manifold, boundary: the
// outcomes Remover::propose decides from what it read alone). When the next
// pass meets the same face again, unchanged (same stamp), and no removal
// since changed a vertex the refusal read, the removal would read the same
// data and be refused the same way: it is not computed again. The tracker's
// outcomes (tolerance, guard) depend on every removal so far and are never
// remembered.
#pragma once

#include <atomic>
#include <cstdint>
#include <memory>
#include <vector>

#include "batch_crew.h"
#include "big_vector.h"
#include "queue.h"
#include "removal.h"

namespace isoform::reduce {

class Speculation {
 public:
  // The removals computed ahead run on `crew` (batch_crew.h).
  // `faces`: the working mesh's face ids (they never grow); `remember`:
  // refusals are remembered from one pass to the next.
  Speculation(size_t vertices, size_t faces, bool remember, BatchCrew& crew)
      : memo_(remember ? faces : 0, 0), changed_(vertices, 0), crew_(crew) {}
  Speculation(const Speculation&) = delete;
  Speculation& operator=(const Speculation&) = delete;
  ~Speculation() { crew_.settle(); }
  // Starts computing, in parallel, the removals of order[begin, end) whose
  // faces are current for `pass` now, and returns when this thread finds
  // none left to start: the others may still be computing theirs, and the
  // methods below wait for an entry's removal where they need it. Nothing
  // may change the mesh before settle().
  void propose(const Remover& remover, const WorkMesh& w, const std::vector<QueueEntry>& order, size_t begin,
               size_t end, int pass);
  // Waits until every removal of the batch is computed; rethrows what a
  // computation threw.
  void settle() { crew_.finish(); }
  // Begins the batch order[begin, end) without computing anything ahead:
  // each removal is then computed when current() asks for it.
  void begin_serial(const WorkMesh& w, const std::vector<QueueEntry>& order, size_t begin, size_t end, int pass);
  // Was entry i current when the batch began? (One that was not is not now:
  // stamps only grow, dead faces stay dead, a face made in a pass keeps it.)
  bool was_current(size_t i) const { return current_[i - begin_] != 0; }
  // Did a removal applied in this batch change what entry i's removal read?
  // (When not, neither did it change entry i's face.) False for an entry
  // not computed yet.
  bool read_changed(size_t i) const;
  // The removal of entry i of the batch as it would be computed now: the
  // one computed ahead when nothing it read has changed since, else
  // computed again.
  const Proposal& current(const Remover& remover, size_t i);
  // Asks for what applying entry i's removal will read and write (only
  // timing depends on it).
  void prefetch(const WorkMesh& w, size_t i) const;
  // Records that p was applied: its vertices changed.
  void applied(const Proposal& p);
  // Records that entry i's removal, as current() gave it, was refused (its
  // outcome one that depends on its own neighbourhood alone), so that the
  // next pass need not compute it again while nothing it read changes.
  void refused(size_t i);

 private:
  // Waits until entry i's removal, computed ahead, is there.
  void wait_for(size_t i) const;
  // Entry e's removal: the refusal the last pass remembered for its face
  // when nothing it read has changed since (out.recalled), else computed.
  void compute(const Remover& remover, const QueueEntry& e, Proposal& out) const;
  bool recall(const QueueEntry& e, Proposal& out) const;

  // A refused removal of the pass `pass`, decided in batch `batch`: its
  // reads are reads_[pass & 1][begin, begin + count).
  struct Refusal {
    int face = -1;
    int pass = 0;
    uint32_t stamp = 0;
    uint32_t batch = 0;
    uint32_t begin = 0, count = 0;
    Outcome outcome = Outcome::Corona;
  };
  BigVector<uint32_t> memo_;            // per face: 1 + its refusal's index, 0: none (empty: off)
  std::vector<Refusal> refusals_[2];    // by the pass's parity: this pass's, the last one's
  std::vector<int> reads_[2];
  int pass_ = 0;

  // Computes the k-th current entry's removal (a crew item).
  struct ComputeAhead {
    Speculation* ahead = nullptr;
    const Remover* remover = nullptr;
    const WorkMesh* w = nullptr;
    void operator()(size_t k) const;
  };
  ComputeAhead compute_;

  std::vector<Proposal> slots_;
  std::unique_ptr<std::atomic<uint8_t>[]> computed_;  // per slot
  size_t capacity_ = 0;             // of computed_
  bool ahead_ = false;              // the batch's removals are computed ahead
  std::vector<uint8_t> current_;    // per slot: current when the batch began
  std::vector<size_t> entries_;     // the batch's current entries
  BigVector<uint32_t> changed_;     // per vertex: the batch that last changed it (big_vector.h)
  std::vector<Box3f> changes_;      // the boxes the batch's applied removals changed (face_grid.h)
  uint32_t batch_ = 0;
  size_t begin_ = 0;
  const std::vector<QueueEntry>* order_ = nullptr;
  BatchCrew& crew_;
};

}  // namespace isoform::reduce

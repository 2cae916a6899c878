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
#pragma once

#include <cstdint>
#include <vector>

#include "queue.h"
#include "removal.h"

namespace isoform::reduce {

class Speculation {
 public:
  explicit Speculation(size_t vertices) : changed_(vertices, 0) {}
  // Computes, in parallel, the removals of order[begin, end) whose faces are
  // current for `pass` now.
  void propose(const Remover& remover, const WorkMesh& w, const std::vector<QueueEntry>& order, size_t begin,
               size_t end, int pass);
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

 private:
  std::vector<Proposal> slots_;
  std::vector<uint8_t> computed_;   // per slot
  std::vector<uint8_t> current_;    // per slot: current when the batch began
  std::vector<size_t> entries_;     // the batch's current entries
  std::vector<uint32_t> changed_;   // per vertex: the batch that last changed it
  uint32_t batch_ = 0;
  size_t begin_ = 0;
  const std::vector<QueueEntry>* order_ = nullptr;
};

}  // namespace isoform::reduce

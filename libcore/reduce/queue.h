// The lazy priority queue of the reduction's passes (Algorithm 5.1, Remark
// 5.9): a pass tries the faces that exist when it starts in increasing
// weight, ties by face id. Entries carry the face's stamp; an entry whose
// face has changed since is stale and skipped.
//
// NOTE: a face's weight ω (5.23) depends only on its vertices' positions and
// absolute curvatures, which change only at the new point, whose faces are
// all new; so the weight is kept per face (WorkMesh::weight, set when the
// face is made) instead of recomputed for every face at every pass, and the
// next pass's order is the current order without its stale entries merged
// with the sorted new faces, instead of a sort of everything. The order is
// the same as a full sort's: (weight, id) is a strict total order.
#pragma once

#include <cstdint>
#include <vector>

#include "work_mesh.h"

namespace isoform::reduce {

struct QueueEntry {
  double weight;
  int face;
  uint32_t stamp;
};

class PassQueue {
 public:
  // The order of the next pass: every live face, lightest first. `pass` is
  // the pass about to start; faces made in pass - 1 are the new ones.
  const std::vector<QueueEntry>& next_pass(const WorkMesh& w, int pass);

 private:
  std::vector<QueueEntry> order_, fresh_, merged_;
  std::vector<uint64_t> old_, made_;  // next_pass's bits: old faces, faces of the last pass
};

// Sets every face's weight (in parallel; each face on its own).
void compute_weights(WorkMesh& w);

}  // namespace isoform::reduce

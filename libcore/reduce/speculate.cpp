// The removals of a pass computed ahead (see speculate.h).
#include "speculate.h"

#include "prefetch.h"

namespace isoform::reduce {
namespace {

// NOTE: the queue visits the mesh in weight order, all over memory, and a
// removal's time is mostly spent waiting for its faces and vertices. The
// entries ahead are known, so their data is fetched early, in four steps
// (the face, then its vertices, then their face lists, then those faces),
// each from what the step before fetched. Only timing depends on it.
// (memo: the remembered refusals, or null.)
void prefetch_ahead(const WorkMesh& w, const std::vector<QueueEntry>& order, const uint32_t* memo, size_t i) {
  constexpr size_t kFace = 24, kVertex = 12, kList = 5, kCorona = 2;
  if (i + kFace < order.size()) {
    const size_t f = size_t(order[i + kFace].face);
    if (memo) prefetch(memo + f);
    prefetch(&w.tri[f]);
    prefetch(&w.face_alive[f]);
    prefetch(&w.face_stamp[f]);
    prefetch(&w.face_pass[f]);
  }
  if (i + kVertex < order.size()) {
    for (int v : w.tri[size_t(order[i + kVertex].face)]) {
      prefetch(w.vfaces.record(size_t(v)));
      prefetch(&w.pos[size_t(v)]);
      prefetch(&w.boundary[size_t(v)]);
    }
  }
  if (i + kList < order.size()) {
    for (int v : w.tri[size_t(order[i + kList].face)]) {
      const FaceLists::Span list = w.vfaces[size_t(v)];
      if (!list.empty()) prefetch(list.begin());
    }
  }
  if (i + kCorona < order.size()) {
    for (int v : w.tri[size_t(order[i + kCorona].face)])
      for (int g : w.vfaces[size_t(v)]) prefetch(&w.tri[size_t(g)]);
  }
}

bool is_current(const WorkMesh& w, const QueueEntry& e, int pass) {
  const size_t f = size_t(e.face);
  return w.face_alive[f] && w.face_stamp[f] == e.stamp && w.face_pass[f] != pass;
}

}  // namespace

void Speculation::propose(const Remover& remover, const WorkMesh& w, const std::vector<QueueEntry>& order,
                          size_t begin, size_t end, int pass) {
  begin_serial(w, order, begin, end, pass);
  ahead_ = true;
  // NOTE: one removal at a time to each thread: a thread that loses its
  // core holds the others up for one removal, not for a share of the batch.
  // The helpers may still run it after this returns: it is a member.
  compute_ = {this, &remover, &w};
  crew_.start(entries_.size(), compute_);
}

void Speculation::ComputeAhead::operator()(size_t k) const {
  const size_t i = ahead->entries_[k];
  const bool recalls = !ahead->memo_.empty() && !ahead->refusals_[(ahead->pass_ - 1) & 1].empty();
  prefetch_ahead(*w, *ahead->order_, recalls ? ahead->memo_.data() : nullptr, i);
  ahead->compute(*remover, (*ahead->order_)[i], ahead->slots_[i - ahead->begin_]);
  ahead->computed_[i - ahead->begin_].store(1, std::memory_order_release);
}

void Speculation::begin_serial(const WorkMesh& w, const std::vector<QueueEntry>& order, size_t begin, size_t end,
                               int pass) {
  ++batch_;
  if (pass != pass_) {  // the buffer of two passes ago is free again
    pass_ = pass;
    refusals_[pass & 1].clear();
    reads_[pass & 1].clear();
  }
  begin_ = begin;
  order_ = &order;
  changes_.clear();
  ahead_ = false;
  const size_t n = end - begin;
  if (slots_.size() < n) slots_.resize(n);
  if (capacity_ < n) {
    computed_.reset(new std::atomic<uint8_t>[n]);
    capacity_ = n;
  }
  for (size_t k = 0; k < n; ++k) computed_[k].store(0, std::memory_order_relaxed);
  current_.assign(n, 0);
  entries_.clear();
  // NOTE: the batch's faces are all over memory and this thread reads them
  // before the helpers have anything to do: asked for all at once, their
  // misses overlap instead of following one another.
  for (size_t i = begin; i < end; ++i) {
    const size_t f = size_t(order[i].face);
    reduce::prefetch(&w.face_alive[f]);
    reduce::prefetch(&w.face_stamp[f]);
    reduce::prefetch(&w.face_pass[f]);
  }
  for (size_t i = begin; i < end; ++i)
    if (is_current(w, order[i], pass)) {
      entries_.push_back(i);
      current_[i - begin] = 1;
    }
}

void Speculation::wait_for(size_t i) const {
  if (!ahead_ || !current_[i - begin_]) return;
  while (!computed_[i - begin_].load(std::memory_order_acquire)) {
    if (crew_.failed()) {
      crew_.finish();  // throws what the computation threw
      return;
    }
    BatchCrew::pause();
  }
}

bool Speculation::read_changed(size_t i) const {
  wait_for(i);
  if (!computed_[i - begin_].load(std::memory_order_acquire)) return false;
  const Proposal& p = slots_[i - begin_];
  for (int v : p.reads)
    if (changed_[size_t(v)] == batch_) return true;
  // The overlap guard read the faces in its boxes (face_grid.h).
  if (!p.region.empty())
    for (const Box3f& b : changes_)
      if (b.meets(p.region)) return true;
  return false;
}

const Proposal& Speculation::current(const Remover& remover, size_t i) {
  Proposal& p = slots_[i - begin_];
  if (!computed_[i - begin_].load(std::memory_order_acquire) || read_changed(i)) {
    compute(remover, (*order_)[i], p);
    computed_[i - begin_].store(1, std::memory_order_relaxed);
  }
  return p;
}

// NOTE: a batch's removals were computed a while ago, or on the other core,
// so their faces and face lists are cold again when their turn comes.
void Speculation::prefetch(const WorkMesh& w, size_t i) const {
  if (i < begin_ || i - begin_ >= current_.size() || !computed_[i - begin_].load(std::memory_order_acquire)) return;
  const Proposal& p = slots_[i - begin_];
  for (int f : p.platelet.faces) {
    reduce::prefetch(&w.tri[size_t(f)]);
    reduce::prefetch(&w.face_stamp[size_t(f)]);
  }
  for (int v : p.reads) {
    reduce::prefetch(&changed_[size_t(v)]);
    reduce::prefetch(w.vfaces.record(size_t(v)));
  }
}

// NOTE: the helpers read changed_ (recall) while this thread marks the
// vertices of the batch's applied removals: relaxed atomic accesses. A
// helper that misses a mark recalls a refusal whose reads read_changed()
// then finds changed, and the removal is computed again before it counts.
void Speculation::applied(const Proposal& p) {
  for (int v : p.platelet.a) __atomic_store_n(&changed_[size_t(v)], batch_, __ATOMIC_RELAXED);
  for (int v : p.platelet.ring) __atomic_store_n(&changed_[size_t(v)], batch_, __ATOMIC_RELAXED);
  if (!p.changes.empty()) changes_.push_back(p.changes);
}

void Speculation::compute(const Remover& remover, const QueueEntry& e, Proposal& out) const {
  if (recall(e, out)) return;
  remover.propose(e.face, out);
  out.recalled = false;
}

// Valid when the refusal is the last pass's, of the face as it is now, and
// no vertex it read changed in its batch or after (a removal applied later
// in the same batch marks its vertices with that batch's number).
bool Speculation::recall(const QueueEntry& e, Proposal& out) const {
  // (The last pass's refusals first: none in the first pass, whose memo
  // would be a cache miss per face for nothing.)
  const std::vector<Refusal>& refusals = refusals_[(pass_ - 1) & 1];
  if (memo_.empty() || refusals.empty()) return false;
  const uint32_t k = __atomic_load_n(&memo_[size_t(e.face)], __ATOMIC_RELAXED);
  if (k == 0) return false;
  if (k > refusals.size()) return false;
  const Refusal& r = refusals[k - 1];
  if (r.face != e.face || r.pass != pass_ - 1 || r.stamp != e.stamp) return false;
  const int* reads = reads_[(pass_ - 1) & 1].data() + r.begin;
  for (uint32_t j = 0; j < r.count; ++j)
    if (__atomic_load_n(&changed_[size_t(reads[j])], __ATOMIC_RELAXED) >= r.batch) return false;
  out.face = e.face;
  out.outcome = r.outcome;
  out.region = out.changes = Box3f();
  out.reads.assign(reads, reads + r.count);
  out.recalled = true;
  return true;
}

void Speculation::refused(size_t i) {
  if (memo_.empty()) return;
  const Proposal& p = slots_[i - begin_];
  const QueueEntry& e = (*order_)[i];
  std::vector<Refusal>& refusals = refusals_[pass_ & 1];
  std::vector<int>& reads = reads_[pass_ & 1];
  Refusal r;
  r.face = e.face;
  r.pass = pass_;
  r.stamp = e.stamp;
  r.batch = batch_;
  r.begin = uint32_t(reads.size());
  r.count = uint32_t(p.reads.size());
  r.outcome = p.outcome;
  reads.insert(reads.end(), p.reads.begin(), p.reads.end());
  refusals.push_back(r);
  __atomic_store_n(&memo_[size_t(e.face)], uint32_t(refusals.size()), __ATOMIC_RELAXED);
}

}  // namespace isoform::reduce

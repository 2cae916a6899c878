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
void prefetch_ahead(const WorkMesh& w, const std::vector<QueueEntry>& order, size_t i) {
  constexpr size_t kFace = 24, kVertex = 12, kList = 5, kCorona = 2;
  if (i + kFace < order.size()) {
    const size_t f = size_t(order[i + kFace].face);
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
  prefetch_ahead(*w, *ahead->order_, i);
  remover->propose((*ahead->order_)[i].face, ahead->slots_[i - ahead->begin_]);
  ahead->computed_[i - ahead->begin_].store(1, std::memory_order_release);
}

void Speculation::begin_serial(const WorkMesh& w, const std::vector<QueueEntry>& order, size_t begin, size_t end,
                               int pass) {
  ++batch_;
  begin_ = begin;
  order_ = &order;
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
  for (int v : slots_[i - begin_].reads)
    if (changed_[size_t(v)] == batch_) return true;
  return false;
}

const Proposal& Speculation::current(const Remover& remover, size_t i) {
  Proposal& p = slots_[i - begin_];
  if (!computed_[i - begin_].load(std::memory_order_acquire) || read_changed(i)) {
    remover.propose((*order_)[i].face, p);
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

void Speculation::applied(const Proposal& p) {
  for (int v : p.platelet.a) changed_[size_t(v)] = batch_;
  for (int v : p.platelet.ring) changed_[size_t(v)] = batch_;
}

}  // namespace isoform::reduce

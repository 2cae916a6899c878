// The removals of a pass computed ahead (see speculate.h).
#include "speculate.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/partitioner.h>

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
  // NOTE: one removal per task (simple partitioner, grain 1): a thread
  // that holds a stolen half of the batch and loses its core would keep
  // the other waiting for all of it; so each thread can take back the
  // other's untouched removals.
  tbb::parallel_for(
      tbb::blocked_range<size_t>(0, entries_.size(), 1),
      [&](const tbb::blocked_range<size_t>& r) {
        for (size_t k = r.begin(); k != r.end(); ++k) {
          const size_t i = entries_[k];
          prefetch_ahead(w, order, i);
          remover.propose(order[i].face, slots_[i - begin]);
          computed_[i - begin] = 1;
        }
      },
      tbb::simple_partitioner());
}

void Speculation::begin_serial(const WorkMesh& w, const std::vector<QueueEntry>& order, size_t begin, size_t end,
                               int pass) {
  ++batch_;
  begin_ = begin;
  order_ = &order;
  if (slots_.size() < end - begin) slots_.resize(end - begin);
  computed_.assign(end - begin, 0);
  current_.assign(end - begin, 0);
  entries_.clear();
  for (size_t i = begin; i < end; ++i)
    if (is_current(w, order[i], pass)) {
      entries_.push_back(i);
      current_[i - begin] = 1;
    }
}

bool Speculation::read_changed(size_t i) const {
  if (!computed_[i - begin_]) return false;
  for (int v : slots_[i - begin_].reads)
    if (changed_[size_t(v)] == batch_) return true;
  return false;
}

const Proposal& Speculation::current(const Remover& remover, size_t i) {
  Proposal& p = slots_[i - begin_];
  if (!computed_[i - begin_] || read_changed(i)) {
    remover.propose((*order_)[i].face, p);
    computed_[i - begin_] = 1;
  }
  return p;
}

// NOTE: a batch's removals were computed a while ago, or on the other core,
// so their faces and face lists are cold again when their turn comes.
void Speculation::prefetch(const WorkMesh& w, size_t i) const {
  if (i < begin_ || i - begin_ >= computed_.size() || !computed_[i - begin_]) return;
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

// The reduction's per-vertex face lists: each vertex's list in one 64-byte
// record (its length and up to 15 face ids), a longer list in a vector of
// its own that the record points to.
//
// NOTE: the removals read and edit the lists of a few dozen vertices each,
// in weight order all over memory. A std::vector per vertex costs two
// dependent cache misses per list (its header, then its heap block), a heap
// block per vertex, and a new one whenever a list outgrows its block; a
// record is one cache line. Lists keep the order of std::vector's
// push_back and erase (the faces' order decides ties downstream), so the
// reduction gives the same bits either way. Valences above 15 are rare.
//
// Edits of different vertices' lists may run side by side (the reduction's
// commits, speculate.h): a short list is its own record, and every step on
// a long list takes a lock, since the long lists share their container.
// Reading a list (operator[]) while another thread edits is not allowed.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <mutex>
#include <vector>

#include "big_vector.h"

namespace isoform::reduce {

class FaceLists {
 public:
  static constexpr int kInline = 15;

  struct Span {
    const int* first;
    const int* last;
    const int* begin() const { return first; }
    const int* end() const { return last; }
    size_t size() const { return size_t(last - first); }
    bool empty() const { return first == last; }
    int front() const { return *first; }
  };

  // `vertices` empty lists.
  void reset(size_t vertices) {
    records_.assign(vertices, Record{});
    spill_.clear();
    free_spill_.clear();
    if (!lock_) lock_ = std::make_unique<std::mutex>();
  }
  size_t vertex_count() const { return records_.size(); }

  Span operator[](size_t v) const {
    const Record& r = records_[v];
    const int* data = r.count <= kInline ? r.slot : spill_[size_t(r.slot[0])].data();
    return Span{data, data + r.count};
  }
  // The cache line that holds v's list (or, when it is long, where it is).
  const void* record(size_t v) const { return &records_[v]; }

  void push_back(size_t v, int face) {
    Record& r = records_[v];
    if (r.count < kInline) {
      r.slot[r.count++] = face;
      return;
    }
    const std::lock_guard<std::mutex> hold(*lock_);
    if (r.count == kInline) {  // moves out of the record
      size_t at = spill_.size();
      if (!free_spill_.empty()) {
        at = free_spill_.back();
        free_spill_.pop_back();
      } else {
        spill_.emplace_back();
      }
      spill_[at].assign(r.slot, r.slot + kInline);
      r.slot[0] = int(at);
    }
    spill_[size_t(r.slot[0])].push_back(face);
    ++r.count;
  }

  // Removes the first occurrence of face from v's list, keeping the order
  // of the rest; the face must be there.
  void erase(size_t v, int face) {
    Record& r = records_[v];
    if (r.count <= kInline) {
      int* at = std::find(r.slot, r.slot + r.count, face);
      std::copy(at + 1, r.slot + r.count, at);
      --r.count;
      return;
    }
    const std::lock_guard<std::mutex> hold(*lock_);
    const size_t index = size_t(r.slot[0]);
    std::vector<int>& list = spill_[index];
    list.erase(std::find(list.begin(), list.end(), face));
    --r.count;
    if (r.count == kInline) back_inline(r, index);
  }

  void clear(size_t v) {
    Record& r = records_[v];
    if (r.count > kInline) {
      const std::lock_guard<std::mutex> hold(*lock_);
      release(size_t(r.slot[0]));
    }
    r.count = 0;
  }

 private:
  struct alignas(64) Record {
    int32_t count = 0;
    int32_t slot[kInline] = {};  // the list, or slot[0]: its index in spill_
  };

  void back_inline(Record& r, size_t index) {
    std::copy(spill_[index].begin(), spill_[index].end(), r.slot);
    release(index);
  }
  void release(size_t index) {
    spill_[index].clear();
    free_spill_.push_back(index);
  }

  BigVector<Record> records_;  // (big_vector.h)
  std::vector<std::vector<int>> spill_;
  std::vector<size_t> free_spill_;
  std::unique_ptr<std::mutex> lock_;  // of spill_ and free_spill_
};

}  // namespace isoform::reduce

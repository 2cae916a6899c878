// The threads that share the short parallel stretches of the reduction's
// passes (reduce.cpp, speculate.h): the calling thread and up to
// max_concurrency - 1 helpers, which wait between stretches by spinning on
// one atomic word instead of going back to the task scheduler.
//
// NOTE: a batch of the passes computes its removals side by side, then
// decides them one at a time, then commits the accepted ones side by side:
// a large reduction runs thousands of stretches, each microseconds long.
// With tbb::parallel_for, each stretch waited for its last item on the
// other thread, and starting and ending it cost about as much as a short
// stretch's whole work. Here a stretch is posted with one atomic store,
// its items are taken one at a time from a shared counter by whichever
// thread comes first, and the caller may leave once nothing is left to
// take, while the helpers finish what they took: the decisions start on
// the removals already computed. Which thread computes an item never
// changes what it computes. An open stretch (open, add, drain) hands its
// items out as they become known: the helpers commit a batch's accepted
// removals while the calling thread decides the next entries, instead of
// waiting for the decisions to end (the decisions are serial, and the
// helpers would otherwise idle throughout them).
#pragma once

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <mutex>
#include <thread>

#include <tbb/task_arena.h>
#include <tbb/task_group.h>

#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>
#endif

namespace isoform::reduce {

class BatchCrew {
 public:
  // Helpers for the other threads of the current task arena (none on one).
  BatchCrew() : owner_(std::this_thread::get_id()) {
    helpers_ = std::max(0, tbb::this_task_arena::max_concurrency() - 1);
    for (int h = 0; h < helpers_; ++h) group_.run([this] { help(); });
  }
  BatchCrew(const BatchCrew&) = delete;
  BatchCrew& operator=(const BatchCrew&) = delete;
  ~BatchCrew() {
    finish_quietly();
    stop_.store(true, std::memory_order_release);
    group_.wait();
  }

  // Calls body(k) for every k in [0, n), here and on the helpers, and
  // returns when every call has returned; rethrows the first exception a
  // call threw, if any. (More than 65,535 items all run here.)
  template <class Body>
  void run(size_t n, const Body& body) {
    start(n, body);
    finish();
  }

  // The same in steps: start() posts the stretch and returns once this
  // thread finds no item left to take (the helpers may still run theirs);
  // finish() waits for every item and rethrows. `body` must live until
  // finish() returns; a stretch must be finished before the next starts.
  template <class Body>
  void start(size_t n, const Body& body) {
    count_ = 0;
    if (helpers_ == 0 || n > kMost) {  // (all here)
      for (size_t k = 0; k < n; ++k) body(k);
      return;
    }
    count_ = n;
    done_.store(0, std::memory_order_relaxed);
    body_.store(&body, std::memory_order_relaxed);
    call_.store([](const void* b, size_t k) { (*static_cast<const Body*>(b))(k); }, std::memory_order_relaxed);
    generation_ = (generation_ + 1) & 0xffffffffu;
    ticket_.store(generation_ << 32 | uint64_t(n) << 16, std::memory_order_release);  // publishes the stretch
    take_items(generation_);
  }
  void finish() {
    finish_quietly();
    if (failed_.load(std::memory_order_acquire)) {
      failed_.store(false, std::memory_order_relaxed);
      std::exception_ptr e;
      std::swap(e, error_);
      std::rethrow_exception(e);
    }
  }
  // Waits for every item, keeping any exception for finish() (for paths
  // that are already failing, and destructors).
  void settle() { finish_quietly(); }
  // Are the current stretch's items all done? (Does not wait.)
  bool all_done() const { return done_.load(std::memory_order_acquire) >= count_; }

  // A stretch whose items are handed out one at a time, for work that
  // becomes known while this thread goes on with something else: open()
  // posts it with no item, add() makes the next item (0, 1, ...) available
  // to the helpers, drain() runs what no helper has taken here and waits
  // for every item added so far (rethrowing as finish() does), after which
  // more may be added. It ends when the next stretch starts. `body` must
  // live until then; at most 65,535 items (more run in add(), here).
  // Without helpers add() runs its item at once.
  template <class Body>
  void open(const Body& body) {
    count_ = added_ = 0;
    done_.store(0, std::memory_order_relaxed);
    body_.store(&body, std::memory_order_relaxed);
    call_.store([](const void* b, size_t k) { (*static_cast<const Body*>(b))(k); }, std::memory_order_relaxed);
    generation_ = (generation_ + 1) & 0xffffffffu;
    ticket_.store(generation_ << 32, std::memory_order_release);
  }
  void add() {
    const size_t k = added_++;
    if (helpers_ == 0 || count_ >= kMost) {
      call_caught(k);
      return;
    }
    ++count_;
    ticket_.fetch_add(uint64_t(1) << 16, std::memory_order_release);  // publishes item k
  }
  void drain() { finish(); }
  // Has an item of the stretch thrown? (finish() rethrows it.)
  bool failed() const { return failed_.load(std::memory_order_acquire); }

  static void pause() {
#if defined(__x86_64__) || defined(__i386__)
    _mm_pause();
#else
    std::this_thread::yield();
#endif
  }

 private:
  // The ticket: the stretch's number, its item count and its next item.
  static constexpr size_t kMost = 0xffff;
  static uint64_t generation_of(uint64_t t) { return t >> 32; }
  static uint32_t count_of(uint64_t t) { return uint32_t(t >> 16) & 0xffffu; }
  static uint32_t next_of(uint64_t t) { return uint32_t(t) & 0xffffu; }

  // NOTE: takes what no helper has taken first: an open stretch's items
  // wait for a helper, and a helper may never run (its task gets no thread
  // when the scheduler's threads are limited after the arena was made); a
  // crew left with items added and not drained (an exception) would wait
  // for them forever.
  void finish_quietly() {
    take_items(generation_);
    while (done_.load(std::memory_order_acquire) < count_) pause();
  }

  // Takes and runs the items of stretch `generation` until none is left.
  // NOTE: an item is claimed by raising the ticket's count from the value
  // read, so a ticket of another stretch (or one already used up) claims
  // nothing. A stretch cannot end while one of its items is claimed and
  // not done, so the stretch read after a claim is the one claimed.
  void take_items(uint64_t generation) {
    uint64_t ticket = ticket_.load(std::memory_order_acquire);
    for (;;) {
      if (generation_of(ticket) != generation) return;
      const uint32_t k = next_of(ticket);
      if (k >= count_of(ticket)) return;
      if (!ticket_.compare_exchange_weak(ticket, ticket + 1, std::memory_order_acq_rel, std::memory_order_acquire))
        continue;
      call_caught(k);
      done_.fetch_add(1, std::memory_order_acq_rel);
      ticket = ticket_.load(std::memory_order_acquire);
    }
  }

  // Runs item k, keeping its exception for finish().
  void call_caught(size_t k) {
    try {
      call_.load(std::memory_order_relaxed)(body_.load(std::memory_order_relaxed), k);
    } catch (...) {
      const std::lock_guard<std::mutex> hold(error_lock_);
      if (!failed_.load(std::memory_order_relaxed)) {
        error_ = std::current_exception();
        failed_.store(true, std::memory_order_release);
      }
    }
  }

  // A helper: waits for stretches until stopped, spinning, then yielding
  // its core, then (after about a millisecond without work, as in a pass's
  // serial stretches) sleeping 50 microseconds at a time.
  static constexpr int kSpins = 4096, kYields = 1024;
  // NOTE: the scheduler may hand a helper's task to the calling thread
  // itself, while it waits for some parallel work of its own: that helper
  // then does nothing (the caller would otherwise wait for itself).
  void help() {
    if (std::this_thread::get_id() == owner_) return;
    int idle = 0;
    while (!stop_.load(std::memory_order_acquire)) {
      const uint64_t ticket = ticket_.load(std::memory_order_acquire);
      if (next_of(ticket) < count_of(ticket)) {
        take_items(generation_of(ticket));
        idle = 0;
        continue;
      }
      ++idle;
      if (idle < kSpins)
        pause();
      else if (idle < kSpins + kYields)
        std::this_thread::yield();
      else
        std::this_thread::sleep_for(std::chrono::microseconds(50));
    }
  }

  using Call = void (*)(const void*, size_t);
  // (Each counter on a cache line of its own: the helpers spin on the
  // ticket while the caller waits on the count done.)
  alignas(64) std::atomic<uint64_t> ticket_{0};  // generation << 32 | items << 16 | next item
  alignas(64) std::atomic<size_t> done_{0};      // the stretch's items done
  alignas(64) std::atomic<bool> stop_{false};
  std::atomic<const void*> body_{nullptr};
  std::atomic<Call> call_{nullptr};
  std::atomic<bool> failed_{false};
  std::exception_ptr error_;
  std::mutex error_lock_;
  uint64_t generation_ = 0;  // the caller's: the stretch's number
  size_t count_ = 0;         // and its items (0: run here)
  size_t added_ = 0;         // an open stretch's items added (some may have run here)
  const std::thread::id owner_;
  int helpers_ = 0;
  tbb::task_group group_;
};

}  // namespace isoform::reduce

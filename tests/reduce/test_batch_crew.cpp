// The crew of the passes' parallel stretches (batch_crew.h): every item runs
// exactly once whatever the number of threads, a stretch's items are all
// done when finish() (or, for an open stretch, drain()) returns, and an
// exception reaches the caller and leaves the crew usable.
#include <gtest/gtest.h>

#include <atomic>
#include <stdexcept>
#include <vector>

#include <tbb/global_control.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include "libcore/reduce/batch_crew.h"

namespace isoform::reduce {
namespace {

// Many short stretches of 0 to 200 items, as the passes post them.
void every_item_once(int threads) {
  tbb::task_arena arena(threads);
  arena.execute([] {
    BatchCrew crew;
    std::vector<std::atomic<int>> hits(200);
    for (int stretch = 0; stretch < 3000; ++stretch) {
      const size_t n = size_t(stretch * 37 % 201);
      for (size_t k = 0; k < n; ++k) hits[k].store(0);
      crew.run(n, [&](size_t k) { hits[k].fetch_add(1); });
      for (size_t k = 0; k < n; ++k) ASSERT_EQ(hits[k].load(), 1) << "stretch " << stretch << " item " << k;
    }
  });
}

TEST(BatchCrew, EveryItemRunsOnceOnOneTwoAndFourThreads) {
  every_item_once(1);
  every_item_once(2);
  every_item_once(4);
}

TEST(BatchCrew, FinishWaitsForTheItemsStartLeftToHelpers) {
  tbb::task_arena arena(4);
  arena.execute([] {
    BatchCrew crew;
    std::vector<std::atomic<int>> done(64);
    for (int stretch = 0; stretch < 500; ++stretch) {
      for (auto& d : done) d.store(0);
      const auto slow = [&](size_t k) {
        volatile double x = 0;
        for (int i = 0; i < 2000; ++i) x = x + 1e-3 * double(i);
        done[k].store(1, std::memory_order_release);
      };
      crew.start(done.size(), slow);
      crew.finish();
      for (size_t k = 0; k < done.size(); ++k) ASSERT_EQ(done[k].load(std::memory_order_acquire), 1);
    }
  });
}

TEST(BatchCrew, AnExceptionReachesTheCallerAndTheCrewGoesOn) {
  tbb::task_arena arena(3);
  arena.execute([] {
    BatchCrew crew;
    std::atomic<int> ran{0};
    EXPECT_THROW(crew.run(100,
                          [&](size_t k) {
                            ran.fetch_add(1);
                            if (k == 57) throw std::runtime_error("item 57");
                          }),
                 std::runtime_error);
    EXPECT_EQ(ran.load(), 100);  // the others still ran
    std::atomic<int> after{0};
    crew.run(50, [&](size_t) { after.fetch_add(1); });
    EXPECT_EQ(after.load(), 50);
  });
}

// An open stretch (open, add, drain) as the passes use it for commits:
// items added one at a time while this thread goes on, drained now and
// then and more added after; each runs once, and drain() returns only when
// every item added so far is done. Then an ordinary stretch on the same crew.
void stream_items_once(int threads) {
  const tbb::global_control most(tbb::global_control::max_allowed_parallelism, size_t(threads));  // (more than the cores)
  tbb::task_arena arena(threads);
  arena.execute([] {
    BatchCrew crew;
    std::vector<std::atomic<int>> hits(128);
    const auto hit = [&](size_t k) { hits[k].fetch_add(1, std::memory_order_relaxed); };
    for (int stretch = 0; stretch < 2000; ++stretch) {
      const size_t n = size_t(stretch * 53 % 129);
      for (size_t k = 0; k < n; ++k) hits[k].store(0);
      crew.open(hit);
      for (size_t k = 0; k < n; ++k) {
        crew.add();
        volatile double x = 0;  // this thread's own work between items
        for (int i = 0; i < int(k % 7) * 50; ++i) x = x + 1e-3 * double(i);
        if (k % 31 == 30) {
          crew.drain();
          for (size_t j = 0; j <= k; ++j) ASSERT_EQ(hits[j].load(), 1) << "stretch " << stretch << " item " << j;
        }
      }
      crew.drain();
      for (size_t k = 0; k < n; ++k) ASSERT_EQ(hits[k].load(), 1) << "stretch " << stretch << " item " << k;
      std::atomic<int> after{0};
      crew.run(n / 2, [&](size_t) { after.fetch_add(1); });
      ASSERT_EQ(after.load(), int(n / 2));
    }
  });
}

TEST(BatchCrew, OpenStretchRunsEveryAddedItemOnceOnOneTwoAndFourThreads) {
  stream_items_once(1);
  stream_items_once(2);
  stream_items_once(4);
}

TEST(BatchCrew, AnExceptionOfAnAddedItemReachesDrain) {
  for (int threads : {1, 3}) {
    tbb::task_arena arena(threads);
    arena.execute([] {
      BatchCrew crew;
      std::atomic<int> ran{0};
      const auto body = [&](size_t k) {
        ran.fetch_add(1);
        if (k == 9) throw std::runtime_error("item 9");
      };
      crew.open(body);
      // Without helpers the item runs in add(); its exception waits for drain().
      for (int k = 0; k < 20; ++k) crew.add();
      EXPECT_THROW(crew.drain(), std::runtime_error);
      EXPECT_EQ(ran.load(), 20);
      std::atomic<int> after{0};
      crew.run(30, [&](size_t) { after.fetch_add(1); });
      EXPECT_EQ(after.load(), 30);
    });
  }
}

// A crew left with items added and not drained (as when an exception
// leaves the passes) runs them itself where no helper can: here the
// scheduler's threads are limited to one after the arena was made, so the
// helper's task gets no thread.
TEST(BatchCrew, ItemsLeftWhereNoHelperRunsRunWhenTheCrewIsLeft) {
  std::atomic<int> warm{0};
  tbb::parallel_for(0, 1000, [&](int) { warm.fetch_add(1); });  // the arena exists
  const tbb::global_control one(tbb::global_control::max_allowed_parallelism, 1);
  std::atomic<int> ran{0};
  const auto body = [&](size_t) { ran.fetch_add(1); };  // (outlives the crew)
  {
    BatchCrew crew;
    crew.open(body);
    for (int k = 0; k < 10; ++k) crew.add();
  }
  EXPECT_EQ(ran.load(), 10);
}

}  // namespace
}  // namespace isoform::reduce

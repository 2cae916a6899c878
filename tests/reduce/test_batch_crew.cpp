// The crew of the passes' parallel stretches (batch_crew.h): every item runs
// exactly once whatever the number of threads, a stretch's items are all
// done when finish() returns, and an exception reaches the caller and
// leaves the crew usable.
#include <gtest/gtest.h>

#include <atomic>
#include <stdexcept>
#include <vector>

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

}  // namespace
}  // namespace isoform::reduce

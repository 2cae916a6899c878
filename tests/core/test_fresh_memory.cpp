// SystemBlock's kept mappings (fresh_memory.h): a freed small block comes
// back with its pages (and so its old contents: a new mapping is zeroed),
// within the process-wide bound; larger blocks are never kept.
#include <gtest/gtest.h>

#include <cstring>
#include <memory>
#include <vector>

#include "libcore/fresh_memory.h"

using namespace isoform;

namespace {

// A size no contour asks for, so other users of the cache in this process
// cannot take or give blocks of it between the steps below.
constexpr size_t kOdd = (size_t(1) << 20) + 3 * 4096;

std::vector<std::unique_ptr<SystemBlock>> blocks(size_t count, size_t bytes, char fill) {
  std::vector<std::unique_ptr<SystemBlock>> v;
  for (size_t i = 0; i < count; ++i) {
    v.push_back(std::make_unique<SystemBlock>(bytes));
    std::memset(v.back()->data(), fill, bytes);
  }
  return v;
}

size_t filled_with(const std::vector<std::unique_ptr<SystemBlock>>& v, size_t bytes, char fill) {
  size_t n = 0;
  for (const auto& b : v) n += b->data()[0] == fill && b->data()[bytes - 1] == fill;
  return n;
}

}  // namespace

TEST(SystemBlock, FreedSmallBlockComesBackWithItsPages) {
  release_kept_blocks();
  char* first;
  {
    SystemBlock a(kOdd);
    std::memset(a.data(), 'x', kOdd);
    first = a.data();
  }
  const SystemBlock b(kOdd);
  EXPECT_EQ(b.data(), first);
  EXPECT_EQ(b.data()[0], 'x');
  EXPECT_EQ(b.data()[kOdd - 1], 'x');
  // A block of another size is not served from it.
  const SystemBlock c(kOdd + 4096);
  EXPECT_NE(c.data()[0], 'x');
}

TEST(SystemBlock, KeptBytesStayWithinTheBound) {
  release_kept_blocks();
  const size_t count = SystemBlock::kCacheBytes / kOdd + 4;
  blocks(count, kOdd, 'y');  // all freed again at once
  std::vector<std::unique_ptr<SystemBlock>> v;
  for (size_t i = 0; i < count; ++i) v.push_back(std::make_unique<SystemBlock>(kOdd));
  // Exactly as many came back as the bound holds; the others are new
  // (zeroed) mappings.
  EXPECT_EQ(filled_with(v, kOdd, 'y'), SystemBlock::kCacheBytes / kOdd);
  v.clear();
  EXPECT_EQ(release_kept_blocks(), (SystemBlock::kCacheBytes / kOdd) * kOdd);
  EXPECT_EQ(release_kept_blocks(), 0u);
}

TEST(SystemBlock, LargeBlocksAreNotKept) {
  release_kept_blocks();
  const size_t large = SystemBlock::kCachedBlock + 4096;
  blocks(1, large, 'z');
  EXPECT_EQ(release_kept_blocks(), 0u);
}

TEST(ScratchArray, SizesRoundUpToPowersOfTwoWhileKept) {
  EXPECT_EQ(scratch_bytes(0), size_t(64) << 10);
  EXPECT_EQ(scratch_bytes(1), size_t(64) << 10);
  EXPECT_EQ(scratch_bytes((size_t(64) << 10) + 1), size_t(128) << 10);
  EXPECT_EQ(scratch_bytes(size_t(3) << 20), size_t(4) << 20);
  EXPECT_EQ(scratch_bytes(SystemBlock::kCachedBlock), SystemBlock::kCachedBlock);
  EXPECT_EQ(scratch_bytes(SystemBlock::kCachedBlock + 8), SystemBlock::kCachedBlock + 8);
}

TEST(ScratchArray, NextArrayOfALikeSizeTakesTheBlock) {
  release_kept_blocks();
  int32_t* first;
  {
    ScratchArray<int32_t> a(100000);  // 400,000 bytes: a 512 KB block
    for (size_t i = 0; i < 100000; ++i) a[i] = int32_t(i);
    first = a.get();
  }
  const ScratchArray<int32_t> b(90000);  // 360,000 bytes: the same 512 KB
  EXPECT_EQ(b.get(), first);
  EXPECT_EQ(b[89999], 89999);
  const ScratchArray<int32_t> empty;
  EXPECT_EQ(empty.get(), nullptr);
  release_kept_blocks();
}

// The reduction's large arrays (big_vector.h): a freed array's mapping
// comes back to the next array that fits, cut to its size; at most
// kBigKeptBytes are kept; vectors on kept mappings start as vectors do.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <vector>

#include "libcore/reduce/big_vector.h"

using namespace isoform::reduce;

namespace {

constexpr size_t kMB = size_t(1) << 20;

bool aligned(const void* p) { return uintptr_t(p) % kBigBytes == 0; }

}  // namespace

TEST(BigVector, FreedArrayComesBackToTheNextOfItsSize) {
  release_kept_big();
  void* p = allocate_big(6 * kMB - 5);
  ASSERT_TRUE(aligned(p));
  std::memset(p, 1, 6 * kMB - 5);
  free_big(p, 6 * kMB - 5);
  void* q = allocate_big(6 * kMB);
  EXPECT_EQ(q, p);
  std::memset(q, 2, 6 * kMB);  // (all of it still mapped and writable)
  free_big(q, 6 * kMB);
  EXPECT_EQ(release_kept_big(), 6 * kMB);
  EXPECT_EQ(release_kept_big(), 0u);
}

TEST(BigVector, ASmallerArrayTakesTheSmallestKeptMappingCutToItsSize) {
  release_kept_big();
  void* large = allocate_big(20 * kMB);
  void* medium = allocate_big(10 * kMB);
  free_big(large, 20 * kMB);
  free_big(medium, 10 * kMB);
  void* small = allocate_big(3 * kMB);  // rounded to 4 MB
  EXPECT_EQ(small, medium);
  EXPECT_TRUE(aligned(small));
  std::memset(small, 3, 4 * kMB);
  // The kept 20 MB, and the 4 MB handed out: its other 6 MB were given back.
  void* other = allocate_big(4 * kMB);
  EXPECT_EQ(other, large);
  free_big(other, 4 * kMB);
  free_big(small, 3 * kMB);
  EXPECT_EQ(release_kept_big(), 8 * kMB);
}

TEST(BigVector, TwoLiveArraysNeverShareAMapping) {
  release_kept_big();
  void* a = allocate_big(4 * kMB);
  free_big(a, 4 * kMB);
  void* b = allocate_big(4 * kMB);
  void* c = allocate_big(4 * kMB);
  EXPECT_EQ(b, a);
  EXPECT_NE(c, b);
  std::memset(b, 4, 4 * kMB);
  std::memset(c, 5, 4 * kMB);
  EXPECT_EQ(static_cast<unsigned char*>(b)[4 * kMB - 1], 4);
  free_big(b, 4 * kMB);
  free_big(c, 4 * kMB);
  release_kept_big();
}

TEST(BigVector, AtMostTheBoundIsKeptTheOldestGivenBackFirst) {
  release_kept_big();
  // Mapped and freed without a write: no memory is used.
  const size_t quarter = kBigKeptBytes / 4;
  std::vector<void*> arrays;
  for (int i = 0; i < 5; ++i) arrays.push_back(allocate_big(quarter));
  for (void* p : arrays) free_big(p, quarter);
  // The first freed went back: the oldest kept one of equal size is now the
  // second.
  void* again = allocate_big(quarter);
  EXPECT_EQ(again, arrays[1]);
  free_big(again, quarter);
  EXPECT_EQ(release_kept_big(), kBigKeptBytes);
}

TEST(BigVector, AVectorOnAKeptMappingStartsAsAnyVector) {
  release_kept_big();
  const size_t n = 3 * kMB / sizeof(int);
  const int* first;
  {
    BigVector<int> v(n, 7);
    first = v.data();
  }
  BigVector<int> w(n);
  EXPECT_EQ(w.data(), first);
  size_t zeros = 0;
  for (int x : w) zeros += x == 0;
  EXPECT_EQ(zeros, n);
  w.clear();
  w.shrink_to_fit();
  release_kept_big();
}

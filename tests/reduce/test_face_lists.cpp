// The reduction's per-vertex face lists (face_lists.h) against a
// std::vector per vertex under the same random edits: the same lists in the
// same order, through lists that outgrow their record and shrink back.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

#include "libcore/reduce/face_lists.h"

namespace isoform::reduce {
namespace {

std::vector<int> as_vector(const FaceLists& lists, size_t v) {
  const FaceLists::Span s = lists[v];
  return std::vector<int>(s.begin(), s.end());
}

TEST(FaceLists, EmptyAfterReset) {
  FaceLists lists;
  lists.reset(5);
  EXPECT_EQ(lists.vertex_count(), 5u);
  for (size_t v = 0; v < 5; ++v) EXPECT_TRUE(lists[v].empty());
}

TEST(FaceLists, LongListMovesOutAndBackInOrder) {
  FaceLists lists;
  lists.reset(2);
  std::vector<int> expected;
  for (int f = 0; f < 20; ++f) {
    lists.push_back(1, 100 + f);
    expected.push_back(100 + f);
    ASSERT_EQ(as_vector(lists, 1), expected) << "after " << f + 1 << " pushes";
  }
  EXPECT_TRUE(lists[0].empty());
  // Down through the record's size: the order of the rest kept.
  for (int f : {105, 119, 100, 110, 111}) {
    lists.erase(1, f);
    expected.erase(std::find(expected.begin(), expected.end(), f));
    ASSERT_EQ(as_vector(lists, 1), expected) << "after erasing " << f;
  }
  EXPECT_EQ(lists[1].size(), 15u);
  lists.push_back(1, 7);
  expected.push_back(7);
  EXPECT_EQ(as_vector(lists, 1), expected);
  lists.clear(1);
  EXPECT_TRUE(lists[1].empty());
  lists.push_back(1, 3);
  EXPECT_EQ(as_vector(lists, 1), std::vector<int>{3});
}

TEST(FaceLists, RandomEditsMatchVectors) {
  std::mt19937 rng(11);
  constexpr size_t kVertices = 40;
  FaceLists lists;
  lists.reset(kVertices);
  std::vector<std::vector<int>> truth(kVertices);
  size_t longest = 0, spilled_edits = 0;
  for (int step = 0; step < 200000; ++step) {
    const size_t v = rng() % kVertices;
    std::vector<int>& t = truth[v];
    const unsigned op = rng() % 100;
    if (op < 52 || t.empty()) {  // lists drift up to well past 15 and back
      const int f = int(rng() % 64);  // repeats: erase takes the first
      lists.push_back(v, f);
      t.push_back(f);
    } else if (op < 99) {
      const int f = t[rng() % t.size()];
      lists.erase(v, f);
      t.erase(std::find(t.begin(), t.end(), f));
    } else {
      lists.clear(v);
      t.clear();
    }
    spilled_edits += t.size() > size_t(FaceLists::kInline) ? 1 : 0;
    longest = std::max(longest, t.size());
    ASSERT_EQ(lists[v].size(), t.size()) << "step " << step;
    ASSERT_EQ(as_vector(lists, v), t) << "step " << step;
  }
  for (size_t v = 0; v < kVertices; ++v) EXPECT_EQ(as_vector(lists, v), truth[v]);
  // The run went through long lists, not only short ones.
  EXPECT_GT(longest, 2u * FaceLists::kInline);
  EXPECT_GT(spilled_edits, 10000u);
}

}  // namespace
}  // namespace isoform::reduce

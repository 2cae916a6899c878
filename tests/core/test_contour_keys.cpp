// The contour's shared-vertex keys: packed into one word where the grid's
// extent allows (packed_keys.h), kept as pairs where it does not, with the
// same mesh either way.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "libcore/contour/packed_keys.h"
#include "libcore/contour/radix_sort.h"
#include "mesh_checks.h"

namespace isoform {
namespace {

std::vector<BrickMesh> bricks_with(const std::vector<std::pair<uint64_t, int32_t>>& shared) {
  BrickMesh bm;
  bm.shared = shared.data();
  bm.shared_count = uint32_t(shared.size());
  return {bm};
}

TEST(RadixSort, SortsLikeAComparisonSortAndKeepsTheOrderOfEqualKeys) {
  std::mt19937_64 rng(11);
  // Sizes around the chunking (2^15 records per chunk, at most 64 chunks),
  // keys of a few bits (many equal) up to 61 bits, some digits constant.
  for (size_t n : {size_t(0), size_t(1), size_t(2), size_t(1000), size_t(40000), size_t(300000), size_t(2500000)})
    for (int bits : {3, 20, 61}) {
      std::vector<std::pair<uint64_t, uint64_t>> records(n), buffer(n);
      for (size_t i = 0; i < n; ++i) {
        uint64_t key = rng() & ((uint64_t(1) << bits) - 1);
        if (bits == 61) key &= ~(uint64_t(0xFF) << 24);  // a digit that is 0 in every key
        records[i] = {key, i};
      }
      std::vector<std::pair<uint64_t, uint64_t>> expected = records;
      std::sort(expected.begin(), expected.end());
      radix_sort(records.data(), buffer.data(), n, bits, [](const std::pair<uint64_t, uint64_t>& r) { return r.first; });
      EXPECT_EQ(records, expected) << n << " records, " << bits << " bits";
    }
}

TEST(RadixSort, SortingAboveLowBitsThatIncreaseGivesTheWholeOrder) {
  // What the merge relies on for the packed keys: the words come with their
  // low bits (the vertex) increasing, so sorting stably by the bits above
  // them orders the whole words.
  std::mt19937_64 rng(12);
  const size_t n = 200000;
  std::vector<uint64_t> words(n), buffer(n);
  for (size_t i = 0; i < n; ++i) words[i] = ((rng() & 0xFFFFF) << 18) | i;
  std::vector<uint64_t> expected = words;
  std::sort(expected.begin(), expected.end());
  radix_sort(words.data(), buffer.data(), n, 38, [](uint64_t w) { return w; }, 18);
  EXPECT_EQ(words, expected);
}

TEST(PackedKeys, PackingKeepsTheOrderOfKeyVertexPairs) {
  std::mt19937 rng(5);
  std::uniform_int_distribution<int> coord(-300, 700), slot(0, 6), vertex(0, 99999);
  std::vector<std::pair<uint64_t, int32_t>> shared;
  for (int n = 0; n < 20000; ++n)
    shared.emplace_back(edge_key(coord(rng), coord(rng) / 3, coord(rng) * 7, slot(rng)), vertex(rng));
  shared.push_back(shared[17]);  // a key met twice, with another vertex
  shared.back().second = 4;
  const PackedLayout layout = packed_layout(bricks_with(shared), 100000);
  ASSERT_TRUE(layout.fits);
  EXPECT_EQ(layout.vertex_bits, 17);
  std::vector<std::pair<uint64_t, uint64_t>> pairs;
  std::vector<uint64_t> words;
  for (const auto& s : shared) {
    pairs.emplace_back(s.first, uint64_t(s.second));
    words.push_back(layout.pack(s.first, uint64_t(s.second)));
  }
  std::sort(pairs.begin(), pairs.end());
  std::sort(words.begin(), words.end());
  for (size_t i = 0; i < pairs.size(); ++i) {
    EXPECT_EQ(words[i] & ((uint64_t(1) << 17) - 1), pairs[i].second);
    if (i > 0) {
      EXPECT_EQ(words[i] >> 17 == words[i - 1] >> 17, pairs[i].first == pairs[i - 1].first);
    }
  }
}

TEST(PackedKeys, KeysSpanningTheWholeIndexRangeDoNotFit) {
  const std::vector<std::pair<uint64_t, int32_t>> shared = {{edge_key(-500000, -500000, -500000, 0), 0},
                                                            {edge_key(500000, 500000, 500000, 2), 1}};
  // 20 bits per axis, 3 for the slot: 63, so no vertex index above 1 fits.
  EXPECT_TRUE(packed_layout(bricks_with(shared), 2).fits);
  EXPECT_FALSE(packed_layout(bricks_with(shared), 3).fits);
  const std::vector<std::pair<uint64_t, int32_t>> near = {{edge_key(-5, 0, 3, 0), 0}, {edge_key(9, 2, 3, 2), 1}};
  EXPECT_TRUE(packed_layout(bricks_with(near), 2).fits);
}

// Two balls of radius 5 in bricks of 8^3 cells, their centres `apart`
// cells from the origin on either side along every axis.
class TwoBalls : public BrickSource {
 public:
  explicit TwoBalls(int apart) : apart_(apart) {
    for (int side : {-1, 1})
      for (int b = 0; b < 8; ++b)
        origins_.push_back({side * apart + 8 * ((b & 1) - 1), side * apart + 8 * (((b >> 1) & 1) - 1),
                            side * apart + 8 * ((b >> 2) - 1)});
  }
  size_t brick_count() const override { return origins_.size(); }
  void fill(size_t index, Brick& out) const override {
    const Index3& o = origins_[index];
    out.resize(o, {8, 8, 8}, false);
    for (int k = -1; k <= 9; ++k)
      for (int j = -1; j <= 9; ++j)
        for (int i = -1; i <= 9; ++i) out.samples[out.at(i, j, k)] = float(f(o[0] + i, o[1] + j, o[2] + k));
  }

 private:
  double f(int x, int y, int z) const {
    const int c = x < 0 ? -apart_ : apart_;
    return std::sqrt(double(x - c) * (x - c) + double(y - c) * (y - c) + double(z - c) * (z - c) + 0.3) - 5.0;
  }
  int apart_;
  std::vector<Index3> origins_;
};

TEST(PackedKeys, FarApartAndNearBallsGiveTheSameClosedMesh) {
  // 400000 cells apart the keys need more than 64 bits with the vertex
  // (the pairs' path); 40 apart they pack. The same cells cross, so the
  // counts agree (the fans may differ: float points 4e5 from the origin
  // round differently, and the apex follows the areas).
  Mesh meshes[2];
  int at = 0;
  for (int apart : {400000, 40}) {
    ScalarGrid grid;
    grid.grid_class = GridClass::LevelSet;
    grid.bricks = std::make_shared<TwoBalls>(apart);
    std::vector<std::pair<uint64_t, int32_t>> corners = {{edge_key(-apart - 8, -apart - 8, -apart - 8, 0), 0},
                                                         {edge_key(apart + 8, apart + 8, apart + 8, 0), 1}};
    EXPECT_EQ(packed_layout(bricks_with(corners), 3000).fits, apart == 40);
    meshes[at++] = test::run_contour(grid, 0.0, ContourMethod::Cells, 2);
  }
  for (const Mesh& m : meshes) {
    EXPECT_EQ(m.part_count, 2);
    EXPECT_EQ(m.stats.boundary_edges, 0);
    EXPECT_EQ(m.stats.nonmanifold_edges, 0);
    EXPECT_EQ(m.stats.inconsistent_edges, 0);
    EXPECT_EQ(m.stats.euler_characteristic, 4);
  }
  EXPECT_EQ(meshes[0].triangles.size(), meshes[1].triangles.size());
  EXPECT_EQ(meshes[0].points.size(), meshes[1].points.size());
  EXPECT_GT(meshes[0].points.size(), 300u);
}

}  // namespace
}  // namespace isoform

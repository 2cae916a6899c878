// The walk of one OpenVDB 5-4-3 tree as RootNode, InternalNode and LeafNode
// read it, with readCompressedValues' chunk layout (see vdb_tree_check.h).
#include "vdb_tree_check.h"

#include <blosc.h>
#include <openvdb/openvdb.h>
#include <zlib.h>

#include <algorithm>
#include <bitset>
#include <cstdio>
#include <cstring>
#include <map>
#include <memory>
#include <vector>

#include "input_file.h"
#include "libcore/errors.h"
#include "vdb_convert.h"

namespace isoform::vdbio {

namespace {

// io::COMPRESS_* and the per-chunk flags of io/Compression.h.
constexpr uint32_t kZip = 0x1, kActiveMask = 0x2, kBlosc = 0x4;
constexpr int8_t kMaskAndNoInactive = 3, kNoMaskAndAllValues = 6;

enum class LeafKind { Values, Bool, Mask };

struct ValueFormat {
  uint64_t size = 0;       // sizeof(ValueType): backgrounds, tiles, inactive values
  uint64_t half_size = 0;  // a value stored as half floats, or 0 if never
  LeafKind leaf = LeafKind::Values;
};

ValueFormat value_format(const ByteCursor& in, const std::string& type) {
  static const std::map<std::string, ValueFormat> formats = {
      {"float", {4, 2, LeafKind::Values}},   {"double", {8, 2, LeafKind::Values}},
      {"int32", {4, 0, LeafKind::Values}},   {"int64", {8, 0, LeafKind::Values}},
      {"vec3i", {12, 0, LeafKind::Values}},  {"vec3s", {12, 6, LeafKind::Values}},
      {"vec3d", {24, 6, LeafKind::Values}},  {"bool", {1, 0, LeafKind::Bool}},
      {"mask", {1, 0, LeafKind::Mask}}};
  const std::string prefix = "Tree_", suffix = "_5_4_3";
  if (type.size() > prefix.size() + suffix.size() && type.compare(0, prefix.size(), prefix) == 0 &&
      type.compare(type.size() - suffix.size(), suffix.size(), suffix) == 0) {
    const auto f = formats.find(type.substr(prefix.size(), type.size() - prefix.size() - suffix.size()));
    if (f != formats.end()) return f->second;
  }
  throw Unsupported(in.path() + ": a grid of type " + type +
                    "; isoform reads 5-4-3 trees of float, double, int32, int64, bool, mask and vec3 values");
}

// A node's masks, as NodeMask::load reads them.
template <size_t Bits>
std::bitset<Bits> read_mask(ByteCursor& in, const char* what) {
  uint64_t words[Bits / 64];
  in.read(words, sizeof words, what);
  std::bitset<Bits> mask;
  for (size_t w = Bits / 64; w-- > 0;) {
    mask <<= 64;
    mask |= std::bitset<Bits>(words[w]);
  }
  return mask;
}

struct Counts {
  uint64_t root_entries = 0, upper = 0, lower = 0, leaves = 0;
  uint64_t tile_blocks = 0;  // 8^3 blocks under active tiles (vdbio's active bricks list them)
};

// What one root child holds for the buffer pass: its leaves' active counts
// (in the order its buffers come) and origins.
struct RootChild {
  int32_t origin[3];
  std::vector<uint16_t> leaf_active;
  std::vector<std::array<int32_t, 3>> leaf_origin;
};

class TreeWalk {
 public:
  TreeWalk(ByteCursor& in, const TreeFormat& format)
      : in_(in), format_(format), value_(value_format(in, format.type)) {}

  void run(uint64_t memory_budget) {
    in_.get<int32_t>("the tree's buffer count");
    raw_values(1, "the background value");
    const uint32_t tiles = in_.get<uint32_t>("the root's tile count");
    const uint32_t children = in_.get<uint32_t>("the root's child count");
    if (tiles == 0 && children == 0) return;
    in_.need(uint64_t(tiles) * (12 + value_.size + 1), "the root's tiles");
    in_.need(uint64_t(children) * (12 + 2 * 4096), "the root's children");
    std::map<std::array<int32_t, 3>, size_t> table;  // as RootNode's, sorted by origin
    for (uint32_t t = 0; t < tiles; ++t) {
      add_root_entry(table, SIZE_MAX);
      raw_values(1, "a root tile's value");
      if (read_bool("a root tile's state")) counts_.tile_blocks += uint64_t(1) << 27;  // (4096 / 8)^3
    }
    for (uint32_t c = 0; c < children; ++c) {
      add_root_entry(table, children_.size());
      children_.emplace_back();
      std::copy(last_key_.begin(), last_key_.end(), children_.back().origin);
      upper_topology(children_.back());
    }
    check_budget(memory_budget);
    for (const auto& entry : table)
      if (entry.second != SIZE_MAX) child_buffers(children_[entry.second]);
  }

 private:
  void add_root_entry(std::map<std::array<int32_t, 3>, size_t>& table, size_t child) {
    in_.read(last_key_.data(), 12, "a root entry's origin");
    for (int32_t x : last_key_)
      if (x & 4095) in_.fail("a root entry at " + where(last_key_) + ", not a multiple of 4096");
    if (!table.emplace(last_key_, child).second) in_.fail("two root entries at " + where(last_key_));
    ++counts_.root_entries;
  }

  static std::string where(const std::array<int32_t, 3>& p) {
    return "(" + std::to_string(p[0]) + ", " + std::to_string(p[1]) + ", " + std::to_string(p[2]) + ")";
  }

  // InternalNode<.., 5>: 32^3 entries of 128^3 voxels each.
  void upper_topology(RootChild& child) {
    ++counts_.upper;
    const auto children = read_mask<32768>(in_, "a node's child mask");
    const auto values = read_mask<32768>(in_, "a node's value mask");
    counts_.tile_blocks += (values & ~children).count() << 12;  // (128 / 8)^3 blocks each
    node_values(32768, values.count(), /*decode=*/true);
    for (size_t i = 0; i < 32768; ++i)
      if (children[i]) {
        const std::array<int32_t, 3> o = {child.origin[0] + int32_t((i >> 10) << 7),
                                          child.origin[1] + int32_t(((i >> 5) & 31) << 7),
                                          child.origin[2] + int32_t((i & 31) << 7)};
        lower_topology(child, o);
      }
  }

  // InternalNode<.., 4>: 16^3 leaves.
  void lower_topology(RootChild& child, const std::array<int32_t, 3>& origin) {
    ++counts_.lower;
    const auto children = read_mask<4096>(in_, "a node's child mask");
    const auto values = read_mask<4096>(in_, "a node's value mask");
    counts_.tile_blocks += (values & ~children).count();
    node_values(4096, values.count(), /*decode=*/true);
    for (size_t i = 0; i < 4096; ++i)
      if (children[i]) {
        ++counts_.leaves;
        child.leaf_active.push_back(uint16_t(read_mask<512>(in_, "a leaf's value mask").count()));
        child.leaf_origin.push_back({origin[0] + int32_t((i >> 8) << 3), origin[1] + int32_t(((i >> 4) & 15) << 3),
                                     origin[2] + int32_t((i & 15) << 3)});
      }
  }

  void child_buffers(const RootChild& child) {
    for (size_t l = 0; l < child.leaf_active.size(); ++l) {
      const size_t active = read_mask<512>(in_, "a leaf's value mask").count();
      if (value_.leaf == LeafKind::Values) {
        if (active != child.leaf_active[l])
          in_.fail("a leaf at " + where(child.leaf_origin[l]) + " whose two value masks differ");
        node_values(512, active, /*decode=*/false);
        continue;
      }
      std::array<int32_t, 3> origin;
      in_.read(origin.data(), 12, "a leaf's origin");
      if (origin != child.leaf_origin[l])
        in_.fail("a leaf at " + where(child.leaf_origin[l]) + " says it lies at " + where(origin));
      if (value_.leaf == LeafKind::Bool) in_.skip(64, "a leaf's values");
    }
  }

  // readCompressedValues: a flag saying what follows, inactive values and
  // a selection mask as it says, then the values (only the active ones
  // under mask compression) in a chunk of the grid's compression.
  void node_values(uint64_t count, uint64_t active, bool decode) {
    const int8_t flag = in_.get<int8_t>("a node's value flag");
    if (flag < 0 || flag > kNoMaskAndAllValues) in_.fail("a node's value flag " + std::to_string(flag));
    if (flag == 2 || flag == 4 || flag == 5) raw_values(1, "an inactive value");
    if (flag == 5) raw_values(1, "an inactive value");
    if (flag >= kMaskAndNoInactive && flag <= 5) in_.skip(count / 8, "a selection mask");
    const uint64_t stored = (format_.compression & kActiveMask) && flag != kNoMaskAndAllValues ? active : count;
    const bool half = format_.half && value_.half_size;
    const uint64_t bytes = stored * (half ? value_.half_size : value_.size);
    if (half && stored == 0) return;  // HalfReader reads nothing then, not even a chunk size
    if (format_.compression & (kBlosc | kZip))
      chunk(bytes, decode);
    else if (decode && bools())
      raw_values(stored, "a node's values");
    else
      in_.skip(bytes, "a node's values");
  }

  // Values read where OpenVDB reads them raw; a bool must be 0 or 1 (any
  // other byte in a bool is undefined behaviour once loaded).
  void raw_values(uint64_t count, const char* what) {
    if (!bools()) return in_.skip(count * value_.size, what);
    in_.need(count, what);
    std::vector<unsigned char> bytes(count);
    in_.read(bytes.data(), bytes.size(), what);
    check_bools(bytes.data(), bytes.size(), what);
  }
  bool read_bool(const char* what) {
    const unsigned char b = in_.get<unsigned char>(what);
    check_bools(&b, 1, what);
    return b != 0;
  }
  void check_bools(const unsigned char* bytes, size_t n, const char* what) const {
    for (size_t i = 0; i < n; ++i)
      if (bytes[i] > 1) in_.fail(std::string(what) + " holds " + std::to_string(bytes[i]) + " where a bool is 0 or 1");
  }
  bool bools() const { return value_.leaf != LeafKind::Values; }

  // bloscFromStream / unzipFromStream: an int64 size, negative (or zero)
  // for raw bytes, positive for a compressed chunk.
  void chunk(uint64_t bytes, bool decode) {
    const int64_t n = in_.get<int64_t>("a chunk size");
    if (n <= 0) {
      if (n == INT64_MIN || uint64_t(-n) != bytes)
        in_.fail("a raw chunk of " + std::to_string(n == INT64_MIN ? 0 : -n) + " bytes where " +
                 std::to_string(bytes) + " are expected");
      if (decode && bools()) return raw_values(bytes, "a node's values");
      return in_.skip(bytes, "a chunk");
    }
    in_.need(uint64_t(n), "a compressed chunk");
    const bool blosc = format_.compression & kBlosc;
    if (blosc) {
      unsigned char header[16];
      if (n < int64_t(sizeof header)) in_.fail("a compressed chunk of " + std::to_string(n) + " bytes");
      const uint64_t at = in_.pos();
      in_.read(header, sizeof header, "a compressed chunk");
      check_blosc_header(in_, header, uint64_t(n), bytes, "a node's values");
      in_.seek(at, "a compressed chunk");
    }
    if (!decode) return in_.skip(uint64_t(n), "a compressed chunk");
    std::vector<unsigned char> packed(size_t(n), 0), plain(bytes + 1, 0);
    in_.read(packed.data(), packed.size(), "a compressed chunk");
    if (blosc) {
      const int got = blosc_decompress_ctx(packed.data(), plain.data(), bytes, 1);
      if (got < 0 || uint64_t(got) != bytes) in_.fail("a node's values do not decode (blosc)");
    } else {
      uLongf got = uLongf(bytes);
      if (uncompress(plain.data(), &got, packed.data(), uLong(n)) != Z_OK || got != bytes)
        in_.fail("a node's values do not decode (zlib)");
    }
    if (bools()) check_bools(plain.data(), bytes, "a node's values");
  }

  // What OpenVDB will hold once it has read the tree: each node's table
  // (a union of a value and a pointer per entry), masks, leaf buffers; and
  // the list of 8^3 blocks under active tiles that vdbio makes for a grid's
  // active set (a single active root tile is 2^27 of them).
  void check_budget(uint64_t budget) const {
    const uint64_t entry = std::max<uint64_t>(value_.size, 8);
    const uint64_t leaf = value_.leaf == LeafKind::Values ? 512 * value_.size + 96 : 160;
    const uint64_t total = counts_.root_entries * 96 + counts_.upper * (32768 * entry + 8192) +
                           counts_.lower * (4096 * entry + 1024) + counts_.leaves * leaf +
                           counts_.tile_blocks * 16;
    if (total > budget)
      throw FormatError(in_.path() + ": a grid of " + std::to_string(counts_.leaves) + " leaves would take " +
                        size_text(total) + " in memory, beyond the budget of " + size_text(budget));
  }

  ByteCursor& in_;
  TreeFormat format_;
  ValueFormat value_;
  Counts counts_;
  std::array<int32_t, 3> last_key_{};
  std::vector<RootChild> children_;
};

}  // namespace

void check_tree(ByteCursor& in, const TreeFormat& format, uint64_t end_pos, uint64_t memory_budget) {
  in.limit(end_pos);
  TreeWalk(in, format).run(memory_budget);
  in.limit(in.size());
}

void check_blosc_header(const ByteCursor& in, const unsigned char* header, uint64_t chunk_bytes,
                        uint64_t expected, const char* what) {
  auto le32 = [header](int at) {
    return uint32_t(header[at]) | uint32_t(header[at + 1]) << 8 | uint32_t(header[at + 2]) << 16 |
           uint32_t(header[at + 3]) << 24;
  };
  const uint32_t nbytes = le32(4), blocksize = le32(8), cbytes = le32(12);
  if (header[0] == 0 || header[0] > BLOSC_VERSION_FORMAT || nbytes != expected || cbytes != chunk_bytes ||
      (nbytes > 0 && blocksize == 0))
    in.fail(std::string("a compressed chunk of ") + what + " whose header says " + std::to_string(nbytes) +
            " bytes from " + std::to_string(cbytes) + ", where " + std::to_string(expected) + " from " +
            std::to_string(chunk_bytes) + " are expected");
  size_t decoded = 0;
  if (blosc_cbuffer_validate(header, size_t(chunk_bytes), &decoded) != 0 || decoded != expected)
    in.fail(std::string("a compressed chunk of ") + what + " with a header blosc refuses");
}

bool metadata_type_registered(const std::string& type) {
  initialize_openvdb();
  return openvdb::Metadata::isRegisteredType(type);
}

bool grid_type_registered(const std::string& type) {
  initialize_openvdb();
  return openvdb::GridBase::isRegistered(type);
}

}  // namespace isoform::vdbio

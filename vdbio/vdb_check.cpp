// The walk of an OpenVDB file's header, metadata, grid table and
// transforms (see vdb_check.h); the trees are walked in vdb_tree_check.cpp.
#include "vdb_check.h"

#include <algorithm>
#include <cctype>
#include <map>
#include <set>

#include "byte_cursor.h"
#include "libcore/errors.h"
#include "vdb_tree_check.h"

namespace isoform::vdbio {

namespace {

constexpr int64_t kVdbMagic = 0x56444220;  // "VDB " as OpenVDB writes it
constexpr uint32_t kOldestReadable = 222;    // the first version with per-grid compression
constexpr const char* kHalfSuffix = "_HalfFloat";
// GridBase::META_SAVE_HALF_FLOAT.
constexpr const char* kHalfFloatMetadata = "is_saved_as_half_float";

// Fixed-size metadata types: OpenVDB reads sizeof(T) bytes whatever length
// the file gives, so the length must be exactly that or the stream would be
// read out of step. "ptidx32/64" are OpenVDB's point-index aliases of int32
// and int64, and so are "ptdataidx32/64".
const std::map<std::string, uint32_t>& fixed_metadata_sizes() {
  static const std::map<std::string, uint32_t> sizes = {
      {"bool", 1},   {"float", 4},  {"double", 8},  {"int32", 4},  {"int64", 8},   {"vec2i", 8},
      {"vec2s", 8},  {"vec2d", 16}, {"vec3i", 12},  {"vec3s", 12}, {"vec3d", 24},  {"vec4i", 16},
      {"vec4s", 16}, {"vec4d", 32}, {"mat4s", 64},  {"mat4d", 128}, {"ptidx32", 4}, {"ptidx64", 8},
      {"ptdataidx32", 4}, {"ptdataidx64", 8}};
  return sizes;
}

// A blosc chunk inside the delayed-load metadata: OpenVDB sizes its buffer
// from the chunk's header, so the header must state the bytes expected,
// or 128 for fewer (OpenVDB's writer pads short arrays to that).
void check_metadata_blosc(ByteCursor& in, uint32_t bytes, uint64_t expected) {
  constexpr uint64_t kPadded = 128;
  unsigned char header[16];
  if (bytes < sizeof header) in.fail("a compressed metadata chunk of " + std::to_string(bytes) + " bytes");
  in.read(header, sizeof header, "a compressed metadata chunk");
  const uint32_t stated = uint32_t(header[4]) | uint32_t(header[5]) << 8 | uint32_t(header[6]) << 16 |
                          uint32_t(header[7]) << 24;
  check_blosc_header(in, header, bytes, expected < kPadded && stated == kPadded ? kPadded : expected,
                     "metadata");
  in.skip(bytes - sizeof header, "a compressed metadata chunk");
}

// io::DelayedLoadMetadata::readValue: a mask byte and an int64 chunk size per
// leaf, each array raw or blosc-compressed; the counts it resizes to must
// fit what a leaf takes in the file (at least 64 bytes each).
void check_delayed_load(ByteCursor& in, uint32_t num_bytes) {
  if (num_bytes == 0) return;
  const uint64_t start = in.pos();
  const uint32_t count = in.get<uint32_t>("the delayed-load metadata");
  if (uint64_t(count) * 64 > in.size())
    in.fail("delayed-load metadata for " + std::to_string(count) + " leaves, more than a file of " +
            std::to_string(in.size()) + " bytes holds");
  const uint32_t mask_bytes = in.get<uint32_t>("the delayed-load metadata");
  if (mask_bytes > 0)
    check_metadata_blosc(in, mask_bytes, count);
  else
    in.skip(count, "the delayed-load masks");
  const uint32_t size_bytes = in.get<uint32_t>("the delayed-load metadata");
  if (size_bytes != UINT32_MAX) {
    if (size_bytes > 0)
      check_metadata_blosc(in, size_bytes, uint64_t(count) * 8);
    else
      in.skip(uint64_t(count) * 8, "the delayed-load chunk sizes");
  }
  const uint64_t used = in.pos() - start;
  if (used > num_bytes)
    in.fail("delayed-load metadata of " + std::to_string(used) + " bytes in a value of " +
            std::to_string(num_bytes));
  in.skip(num_bytes - used, "the delayed-load metadata");
}

// MetaMap::readMeta. Unknown types are read by OpenVDB as raw bytes of the
// given length; known ones by their own readers. Returns whether the
// metadata say the grid's reals are stored as half floats: OpenVDB's
// readers follow the grid's metadata "is_saved_as_half_float" (a bool; the
// last entry of that name counts), not the grid type name's suffix, since
// reading the metadata replaces what the descriptor set.
bool check_metadata(ByteCursor& in) {
  bool half = false;
  const uint32_t count = in.get<uint32_t>("the metadata count");
  for (uint32_t i = 0; i < count; ++i) {
    const std::string name = in.string("a metadata name");
    const std::string type = in.string("a metadata type name");
    const uint32_t num_bytes = in.get<uint32_t>("a metadata length");
    const auto fixed = fixed_metadata_sizes().find(type);
    if (name == kHalfFloatMetadata && type != "bool")
      in.fail("metadata '" + name + "' of type " + type + ", where OpenVDB expects a bool");
    if (type == "__delayedload") {
      check_delayed_load(in, num_bytes);
    } else if (fixed != fixed_metadata_sizes().end()) {
      if (num_bytes != fixed->second)
        in.fail("metadata '" + name + "' of type " + type + " says " + std::to_string(num_bytes) +
                " bytes, not " + std::to_string(fixed->second));
      if (type == "bool") {
        const unsigned char value = in.get<unsigned char>("a metadata value");
        if (value > 1) in.fail("metadata '" + name + "' holds " + std::to_string(value) + " where a bool is 0 or 1");
        if (name == kHalfFloatMetadata) half = value == 1;
      } else {
        in.skip(num_bytes, "a metadata value");
      }
    } else if (type == "string" || !metadata_type_registered(type)) {
      in.skip(num_bytes, "a metadata value");
    } else {
      throw Unsupported(in.path() + ": metadata '" + name + "' has type " + type +
                        ", which isoform does not read");
    }
  }
  return half;
}

// The maps of math/Maps.h: their read() takes a fixed number of doubles.
uint64_t affine_map_bytes(const std::string& type) {
  if (type == "AffineMap" || type == "UnitaryMap") return 16 * 8;
  if (type == "ScaleMap" || type == "UniformScaleMap") return 5 * 24;
  if (type == "TranslationMap") return 24;
  if (type == "ScaleTranslateMap" || type == "UniformScaleTranslateMap") return 6 * 24;
  return 0;
}

// Transform::read: a map type name, then the map.
void check_transform(ByteCursor& in) {
  const std::string type = in.string("a transform type name");
  if (const uint64_t n = affine_map_bytes(type)) return in.skip(n, "a transform");
  if (type != "NonlinearFrustumMap") throw Unsupported(in.path() + ": transform of type '" + type + "'");
  in.skip(48 + 16, "a frustum transform");  // its box, taper and depth
  const std::string second = in.string("a frustum's second map type name");
  const uint64_t n = affine_map_bytes(second);
  if (!n) throw Unsupported(in.path() + ": a frustum transform whose second map is '" + second + "'");
  in.skip(n, "a frustum's second map");
}

void check_compression(ByteCursor& in) {
  const uint32_t flags = in.get<uint32_t>("a grid's compression flags");
  if (flags & ~uint32_t(0x7)) in.fail("unknown compression flags " + std::to_string(flags));
}

// Archive::readHeader as io::File::open calls it, for versions 222 and on.
uint32_t check_header(ByteCursor& in) {
  if (in.size() < 8 || in.get<int64_t>("the magic number") != kVdbMagic)
    throw FormatError(in.path() + ": not an OpenVDB file");
  const uint32_t version = in.get<uint32_t>("the file version");
  if (version < kOldestReadable)
    throw Unsupported(in.path() + ": OpenVDB file version " + std::to_string(version) + " is older than " +
                      std::to_string(kOldestReadable) + ", the oldest OpenVDB reads");
  in.skip(8, "the library version");
  char has_offsets = in.get<char>("the grid offsets flag");
  if (!has_offsets) throw Unsupported(in.path() + ": an OpenVDB stream without a grid table");
  // The UUID, as text; boost's reader would skip leading white space and
  // so read out of step, so exactly 8-4-4-4-12 hex digits are required.
  char uuid[36];
  in.read(uuid, sizeof uuid, "the file's UUID");
  for (int k = 0; k < 36; ++k) {
    const bool dash = k == 8 || k == 13 || k == 18 || k == 23;
    if (dash ? uuid[k] != '-' : !std::isxdigit(static_cast<unsigned char>(uuid[k])))
      in.fail("the file's UUID is not 36 characters of hex digits and dashes");
  }
  return version;
}

// GridDescriptor::read, then where the descriptor says the grid lies.
VdbGridEntry check_descriptor(ByteCursor& in) {
  VdbGridEntry g;
  g.unique_name = in.string("a grid name");
  g.type = in.string("a grid type name");
  const std::string suffix = kHalfSuffix;
  if (g.type.size() >= suffix.size() && g.type.compare(g.type.size() - suffix.size(), suffix.size(), suffix) == 0) {
    g.half = true;
    g.type.resize(g.type.size() - suffix.size());
  }
  g.parent = in.string("a grid's parent name");
  if (!grid_type_registered(g.type)) throw Unsupported(in.path() + ": grid type " + g.type + " is not one OpenVDB reads");
  g.grid_pos = in.get<int64_t>("a grid's position");
  g.block_pos = in.get<int64_t>("a grid's position");
  g.end_pos = in.get<int64_t>("a grid's position");
  const int64_t size = int64_t(in.size());
  // An instance has no tree of its own, and OpenVDB gives it no block
  // position: its metadata and transform end where it ends.
  if (!g.parent.empty() && g.block_pos == 0) g.block_pos = g.end_pos;
  if (!(in.pos() <= uint64_t(g.grid_pos) && g.grid_pos <= g.block_pos && g.block_pos <= g.end_pos &&
        g.end_pos <= size))
    in.fail("grid '" + g.unique_name + "' is said to lie at bytes " + std::to_string(g.grid_pos) + ", " +
            std::to_string(g.block_pos) + " and " + std::to_string(g.end_pos) + " of " + std::to_string(size));
  return g;
}

// GridDescriptor::nameAsString: OpenVDB's separator before a repeat's
// number becomes "[N]".
std::string readable_name(const std::string& unique) {
  const size_t sep = unique.find('\x1e');
  return sep == std::string::npos ? unique : unique.substr(0, sep) + "[" + unique.substr(sep + 1) + "]";
}

// The grid io::File::findDescriptor picks for a name as readGrid takes it
// (with its stringAsUniqueName and stripSuffix), or -1: the first grid of
// that name, else the one whose stored name matches "name[N]".
int find_descriptor(const std::vector<std::string>& stored, const std::string& name) {
  std::string unique = name;
  if (!unique.empty() && unique.back() == ']' && unique.find('[') != std::string::npos) {
    unique.pop_back();
    unique.replace(unique.find('['), 1, "\x1e");
  }
  const auto strip = [](const std::string& n) { return n.substr(0, n.find('\x1e')); };
  std::vector<int> range;
  for (size_t i = 0; i < stored.size(); ++i)
    if (strip(stored[i]) == name) range.push_back(int(i));
  if (range.empty())
    for (size_t i = 0; i < stored.size(); ++i)
      if (strip(stored[i]) == strip(unique)) range.push_back(int(i));
  if (range.empty()) return -1;
  if (name == unique) return range.front();
  for (const int i : range)
    if (stored[size_t(i)] == unique || stored[size_t(i)] == name) return i;
  return -1;
}

// Every grid must be the one OpenVDB finds by the name isoform will ask it
// for, and an instance's parent the grid OpenVDB finds by the parent's
// name: otherwise OpenVDB would read a tree other than the one walked.
void check_names(const ByteCursor& in, std::vector<VdbGridEntry>& grids) {
  std::vector<std::string> stored;
  for (const VdbGridEntry& g : grids) stored.push_back(g.unique_name);
  for (size_t i = 0; i < grids.size(); ++i) {
    VdbGridEntry& g = grids[i];
    if (find_descriptor(stored, readable_name(g.unique_name)) != int(i))
      in.fail("grid '" + readable_name(g.unique_name) + "' cannot be told apart from another grid's name");
    if (g.parent.empty()) continue;
    g.parent_index = find_descriptor(stored, readable_name(g.parent));
    if (g.parent_index < 0 || !grids[size_t(g.parent_index)].parent.empty())
      in.fail("grid '" + readable_name(g.unique_name) + "' instances '" + readable_name(g.parent) +
              "', which the file lacks or which is an instance itself");
  }
}

}  // namespace

VdbLayout check_vdb_layout(const std::string& path) {
  ByteCursor in(path, "truncated or damaged OpenVDB file");
  VdbLayout layout;
  layout.file_size = in.size();
  layout.version = check_header(in);
  check_metadata(in);
  const int32_t count = in.get<int32_t>("the grid count");
  if (count < 0) in.fail("a grid count of " + std::to_string(count));
  std::set<std::string> names;
  for (int32_t i = 0; i < count; ++i) {
    VdbGridEntry g = check_descriptor(in);
    if (!names.insert(g.unique_name).second) in.fail("two grids named '" + readable_name(g.unique_name) + "'");
    in.seek(uint64_t(g.end_pos), "the next grid descriptor");
    layout.grids.push_back(std::move(g));
  }
  // What io::File::readGridMetadata reads of each grid: compression,
  // metadata, transform; all before the grid's tree begins.
  for (VdbGridEntry& g : layout.grids) {
    in.seek(uint64_t(g.grid_pos), "a grid");
    in.limit(uint64_t(g.block_pos));
    check_compression(in);
    g.half = check_metadata(in);
    check_transform(in);
    in.limit(in.size());
  }
  check_names(in, layout.grids);
  for (VdbGridEntry& g : layout.grids) {
    g.unique_name = readable_name(g.unique_name);
    g.parent = readable_name(g.parent);
  }
  return layout;
}

void check_vdb_grid(const std::string& path, const VdbLayout& layout, int i, uint64_t memory_budget) {
  const VdbGridEntry& g = layout.grids.at(size_t(i));
  if (g.parent_index >= 0) return check_vdb_grid(path, layout, g.parent_index, memory_budget);
  ByteCursor in(path, "truncated or damaged OpenVDB file");
  if (in.size() != layout.file_size)
    throw FormatError(path + ": the file changed after it was opened; open it again");
  // Past the compression, metadata and transform, which check_vdb_layout
  // walked; they are walked again here for the compression flags.
  in.seek(uint64_t(g.grid_pos), "a grid");
  in.limit(uint64_t(g.block_pos));
  const uint32_t compression = in.get<uint32_t>("a grid's compression flags");
  const bool half = check_metadata(in);
  check_transform(in);
  in.limit(in.size());
  check_tree(in, TreeFormat{g.type, half, compression}, uint64_t(g.end_pos), memory_budget);
}

}  // namespace isoform::vdbio

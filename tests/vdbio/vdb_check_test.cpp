// The walk of an OpenVDB file before OpenVDB reads it (vdbio/vdb_check.h):
// every kind of file OpenVDB writes passes and reads back whole; each
// hostile file of the fuzzing is refused with its name and what is wrong,
// before anything is allocated from a size it gives.
#include "vdbio/vdb_check.h"

#include <gtest/gtest.h>
#include <openvdb/io/Compression.h>

#include <malloc.h>

#include <cstring>
#include <fstream>
#include <functional>

#include "libcore/errors.h"
#include "test_support.h"
#include "vdb_samples.h"
#include "vdbio/dense_read.h"
#include "vdbio/input_file.h"
#include "vdbio/vdb_file.h"

namespace isoform::vdbio {
namespace {

using test::error_of;
using test::TempDir;

std::string read_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

void write_bytes(const std::string& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary) << bytes;
}

template <class T>
T load(const std::string& bytes, size_t at) {
  T v;
  std::memcpy(&v, bytes.data() + at, sizeof v);
  return v;
}

template <class T>
void store(std::string& bytes, size_t at, T v) {
  std::memcpy(&bytes[at], &v, sizeof v);
}

// Opens the file as the CLI and the add-on do and reads every grid.
void open_and_read_all(const std::string& path) {
  const auto file = open_vdb(path);
  for (int i = 0; i < file->grid_count(); ++i) dynamic_cast<const VdbFile&>(*file).read_grid(i);
}

// The message of whatever body throws, or "".
template <class Body>
std::string error_of_any(Body&& body) {
  try {
    body();
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

TEST(VdbCheck, EveryKindOpenVdbWritesPassesAndReadsBackWhole) {
  TempDir dir;
  for (const test::VdbSample& sample : test::vdb_samples())
    for (const uint32_t compression : test::vdb_compressions()) {
      SCOPED_TRACE(sample.name + ", compression " + std::to_string(compression));
      const std::string path = dir.file("sample.vdb");
      test::write_vdb_sample(sample, compression, path);
      const std::string refused = error_of_any([&] { open_and_read_all(path); });
      ASSERT_EQ(refused, "") << sample.name << ", compression " << compression;
      const VdbLayout layout = check_vdb_layout(path);
      ASSERT_EQ(layout.grids.size(), sample.grids.size());
      const auto file = open_vdb(path);
      for (int i = 0; i < file->grid_count(); ++i) {
        check_vdb_grid(path, layout, i, default_memory_budget());
        const auto grid = dynamic_cast<const VdbFile&>(*file).read_grid(i);
        EXPECT_EQ(grid->activeVoxelCount(), sample.grids[size_t(i)]->activeVoxelCount());
        EXPECT_EQ(grid->getName(), sample.grids[size_t(i)]->getName());
      }
    }
}

// A fog volume of whole leaves (each leaf's values one blosc chunk of 2,048
// bytes), written by OpenVDB and returned as bytes.
// OpenVDB never zips fog volumes or level sets, so the zip tests take a grid
// of no class.
std::string fog_bytes(const TempDir& dir, uint32_t compression = openvdb::io::COMPRESS_BLOSC,
                      openvdb::GridClass grid_class = openvdb::GRID_FOG_VOLUME) {
  auto grid = openvdb::FloatGrid::create(0.0f);
  grid->setName("density");
  grid->setGridClass(grid_class);
  for (int i = 0; i < 24; ++i)
    for (int j = 0; j < 24; ++j)
      for (int k = 0; k < 24; ++k) grid->tree().setValue(openvdb::Coord(i, j, k), float(i + j * k % 7));
  const std::string path = dir.file("fog.vdb");
  test::write_vdb_sample({"fog", {grid}}, compression, path);
  return read_bytes(path);
}

// Where the first leaf's blosc chunk size lies: an int64 n followed by a
// blosc header saying 2,048 bytes decoded from n.
size_t first_leaf_chunk(const std::string& bytes) {
  for (size_t at = 0; at + 24 <= bytes.size(); ++at) {
    const int64_t n = load<int64_t>(bytes, at);
    if (n > 16 && bytes[at + 8] == 2 && load<uint32_t>(bytes, at + 12) == 2048 &&
        load<uint32_t>(bytes, at + 20) == uint32_t(n))
      return at;
  }
  ADD_FAILURE() << "no leaf chunk found";
  return 0;
}

// Where a length-prefixed string s lies (its length field).
size_t string_at(const std::string& bytes, const std::string& s, size_t from = 0) {
  std::string prefixed(4, '\0');
  store<uint32_t>(prefixed, 0, uint32_t(s.size()));
  const size_t at = bytes.find(prefixed + s, from);
  EXPECT_NE(at, std::string::npos) << s;
  return at;
}

struct Hostile {
  std::string name;
  std::function<void(std::string&)> change;
  std::string message;  // what the error says after "<path>: "
};

std::vector<Hostile> hostile_cases() {
  return {
      {"negative chunk size",  // OpenVDB's bloscFromStream writes past its buffer
       [](std::string& b) { store<int64_t>(b, first_leaf_chunk(b), -100000); },
       "truncated or damaged OpenVDB file (a raw chunk of 100000 bytes where 2048 are expected)"},
      {"huge chunk size",  // a petabyte new[]
       [](std::string& b) { store<int64_t>(b, first_leaf_chunk(b), 1000000000000000LL); },
       "needs 1000000000000000 bytes but"},
      {"huge type name length",  // GridDescriptor::read allocates 7.5 GB
       [](std::string& b) { store<uint32_t>(b, string_at(b, "density") + 4 + 7, 1918107664u); },
       "a grid type name at byte"},
      {"huge metadata string",  // StringMetadata::readValue allocates it
       [](std::string& b) { store<uint32_t>(b, string_at(b, "string", string_at(b, "class")) + 10, 2000000000u); },
       "a metadata value at byte"},
      {"huge metadata name",
       [](std::string& b) { store<uint32_t>(b, string_at(b, "class"), 1900000000u); },
       "a metadata name at byte"},
      {"blosc header that lies",  // decoded size in the header changed
       [](std::string& b) { store<uint32_t>(b, first_leaf_chunk(b) + 12, 4096u); },
       "a compressed chunk of a node's values whose header says 4096 bytes"},
      {"negative grid count",
       [](std::string& b) { store<int32_t>(b, string_at(b, "density") - 4, -5); },
       "a grid count of -5"},
      {"grid beyond the file",
       [](std::string& b) { store<int64_t>(b, string_at(b, "density") + 4 + 7 + 4 + 16 + 4 + 16, int64_t(1) << 40); },
       "is said to lie at bytes"},
      {"UUID with leading blanks",
       [](std::string& b) { b[8 + 4 + 8 + 1] = ' '; },
       "the file's UUID is not 36 characters"},
  };
}

TEST(VdbCheck, HostileFilesAreRefusedWithTheirNameBeforeOpenVdbReadsThem) {
  TempDir dir;
  const std::string good = fog_bytes(dir);
  for (const Hostile& h : hostile_cases()) {
    SCOPED_TRACE(h.name);
    std::string bytes = good;
    h.change(bytes);
    ASSERT_NE(bytes, good);
    const std::string path = dir.file("hostile.vdb");
    write_bytes(path, bytes);
    const std::string message = error_of<FormatError>([&] { open_and_read_all(path); });
    EXPECT_EQ(message.rfind(path + ": ", 0), 0u) << message;
    EXPECT_NE(message.find(h.message), std::string::npos) << message;
  }
}

// The same chunk, in a zip file: a raw chunk of the wrong size and a
// compressed one that does not decode inside an internal node (which
// OpenVDB would leak half built) are refused.
TEST(VdbCheck, ZipChunksAreCheckedToo) {
  TempDir dir;
  const std::string good = fog_bytes(dir, openvdb::io::COMPRESS_ZIP, openvdb::GRID_UNKNOWN);
  // The first small zlib chunk is the upper node's values (all zero).
  std::string bytes = good;
  size_t chunk = 0;
  for (size_t at = 0; at + 8 <= bytes.size(); ++at)
    if (load<int64_t>(bytes, at) > 0 && load<int64_t>(bytes, at) < 200 && bytes[at + 8] == 0x78) {
      chunk = at;  // a zlib stream starts with 0x78
      break;
    }
  ASSERT_GT(chunk, 0u);
  bytes[chunk + 10] = char(bytes[chunk + 10] ^ 0x55);
  const std::string path = dir.file("zip.vdb");
  write_bytes(path, bytes);
  const std::string message = error_of<FormatError>([&] { open_and_read_all(path); });
  EXPECT_NE(message.find("do not decode (zlib)"), std::string::npos) << message;
}

// A bool that is neither false nor true (undefined behaviour once OpenVDB
// loads it): a root tile's state of 2.
TEST(VdbCheck, BoolsThatAreNeitherFalseNorTrueAreRefused) {
  TempDir dir;
  const std::string path = dir.file("float.vdb");
  test::write_vdb_sample(test::vdb_samples().front(), openvdb::io::COMPRESS_BLOSC, path);
  std::string bytes = read_bytes(path);
  // The root tile at (4096, 0, 0) of value 1.5, active.
  std::string tile(12 + 4 + 1, '\0');
  store<int32_t>(tile, 0, 4096);
  store<float>(tile, 12, 1.5f);
  tile[16] = 1;
  const size_t at = bytes.find(tile);
  ASSERT_NE(at, std::string::npos);
  bytes[at + 16] = 2;
  write_bytes(path, bytes);
  const std::string message = error_of<FormatError>([&] { open_and_read_all(path); });
  EXPECT_NE(message.find("a root tile's state holds 2 where a bool is 0 or 1"), std::string::npos) << message;
}

// Two grids whose names OpenVDB cannot tell apart ("a" stored after "a",
// numbered by OpenVDB's separator): readGrid("a") would give the first
// grid's tree for the second.
TEST(VdbCheck, GridsOpenVdbCannotTellApartAreRefused) {
  TempDir dir;
  auto first = openvdb::FloatGrid::create(0.0f), second = openvdb::FloatGrid::create(0.0f);
  first->setName(std::string("a") + '\x1e' + "0");
  second->setName("a");
  first->tree().setValue(openvdb::Coord(0), 1.0f);
  second->tree().setValue(openvdb::Coord(9), 2.0f);
  const std::string path = dir.file("names.vdb");
  test::write_grids(path, {first, second});
  const std::string message = error_of<FormatError>([&] { check_vdb_layout(path); });
  EXPECT_NE(message.find("cannot be told apart from another grid's name"), std::string::npos) << message;
}

TEST(VdbCheck, ATreeBeyondTheBudgetIsRefused) {
  TempDir dir;
  write_bytes(dir.file("fog.vdb"), fog_bytes(dir));
  const VdbLayout layout = check_vdb_layout(dir.file("fog.vdb"));
  check_vdb_grid(dir.file("fog.vdb"), layout, 0, uint64_t(64) << 20);
  const std::string message =
      error_of<FormatError>([&] { check_vdb_grid(dir.file("fog.vdb"), layout, 0, uint64_t(1) << 18); });
  EXPECT_NE(message.find("a grid of 27 leaves would take 353.6 KiB in memory, beyond the budget of 256.0 KiB"),
            std::string::npos)
      << message;
}

}  // namespace
}  // namespace isoform::vdbio

namespace isoform::vdbio {
namespace {

// Bytes in use on the heap (glibc's count of allocated, not yet freed).
size_t heap_in_use() { return mallinfo2().uordblks; }

// A host such as Blender pays every failed open: a thousand of them, after
// a few to warm up caches, must hold no more memory than one. The files fail
// where isoform checks them, inside OpenVDB (a leaf chunk that does not
// decode), and inside Teem (a header it refuses).
TEST(VdbCheck, AThousandFailedOpensHoldNoMoreMemoryThanOne) {
  TempDir dir;
  std::string corrupt = fog_bytes(dir);
  const size_t chunk = first_leaf_chunk(corrupt);
  for (size_t k = 24; k < 64; ++k) corrupt[chunk + k] = char(0xff);  // inside the compressed data
  std::string negative = fog_bytes(dir);
  store<int64_t>(negative, first_leaf_chunk(negative), -100000);
  write_bytes(dir.file("corrupt.vdb"), corrupt);
  write_bytes(dir.file("negative.vdb"), negative);
  write_bytes(dir.file("garbled.nrrd"), "NRRD0004\ntype: nonsense\ndimension: 3\n\n");
  // Gzip data that end early: Teem's reader would leak its stream.
  std::string gzip = "NRRD0004\ntype: uchar\ndimension: 3\nsizes: 4 4 4\nencoding: gzip\n\n";
  gzip += std::string("\x1f\x8b\x08\x00\x00\x00\x00\x00\x00\x03\x63\x60", 12);
  write_bytes(dir.file("short.nrrd"), gzip);
  const std::vector<std::function<void()>> opens = {
      [&] { open_and_read_all(dir.file("corrupt.vdb")); },
      [&] { open_and_read_all(dir.file("negative.vdb")); },
      [&] { read_nrrd(dir.file("garbled.nrrd")); },
      [&] { read_nrrd(dir.file("short.nrrd")); },
  };
  for (size_t k = 0; k < opens.size(); ++k) {
    SCOPED_TRACE(k);
    for (int i = 0; i < 5; ++i) EXPECT_ANY_THROW(opens[k]());
    const size_t before = heap_in_use();
    for (int i = 0; i < 1000; ++i) EXPECT_ANY_THROW(opens[k]());
    const size_t after = heap_in_use();
    EXPECT_LT(after, before + (64 << 10)) << "grew by " << (after - before) << " bytes";
  }
}

// fuzz_vdb found a file whose grid type name says half floats but whose
// metadata "is_saved_as_half_float" had been renamed: OpenVDB follows the
// metadata and read the tree as full floats, out of step with the walk,
// building 2,048 leaves from bytes the walk counted as 175. The walk now
// follows the metadata as OpenVDB does: such a file is refused, and a file
// whose metadata say half floats is walked as half floats.
TEST(VdbCheck, HalfFloatsAreWhatTheGridsMetadataSay) {
  TempDir dir;
  auto grid = openvdb::FloatGrid::create(0.0f);
  grid->setName("density");
  for (int i = 0; i < 24; ++i)
    for (int j = 0; j < 24; ++j) grid->tree().setValue(openvdb::Coord(i, j, i % 5), float(i + j));
  grid->setSaveFloatAsHalf(true);
  const std::string path = dir.file("half.vdb");
  test::write_vdb_sample({"half", {grid}}, openvdb::io::COMPRESS_NONE, path);
  const std::string bytes = read_bytes(path);
  const VdbLayout layout = check_vdb_layout(path);
  ASSERT_TRUE(layout.grids.at(0).half);
  check_vdb_grid(path, layout, 0, default_memory_budget());

  const size_t at = bytes.find("is_saved_as_half_float");
  ASSERT_NE(at, std::string::npos);
  std::string renamed = bytes;
  renamed[at] = 'X';  // the name OpenVDB looks for is gone: full floats
  write_bytes(path, renamed);
  EXPECT_FALSE(check_vdb_layout(path).grids.at(0).half);
  const std::string message = error_of<FormatError>([&] { check_vdb_grid(path, check_vdb_layout(path), 0, default_memory_budget()); });
  EXPECT_EQ(message.rfind(path + ": ", 0), 0u) << message;

  // The bool itself: "bool" type name, 4-byte length, then the value byte.
  const size_t value = at + std::string("is_saved_as_half_float").size() + 4 + 4 + 4;
  ASSERT_EQ(bytes[value], 1);
  std::string two = bytes;
  two[value] = 2;
  write_bytes(path, two);
  EXPECT_NE(error_of<FormatError>([&] { check_vdb_layout(path); }).find("where a bool is 0 or 1"), std::string::npos);
}

}  // namespace
}  // namespace isoform::vdbio

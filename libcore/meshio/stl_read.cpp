// Reading STL, binary or ascii. STL stores each triangle with its own three
// corners, so corners with exactly the same coordinates are welded into one
// vertex to give the shared-vertex table the rest of isoform works on.
// Facet normals are not kept: they are per triangle, Mesh normals per vertex.
#include <array>
#include <cmath>
#include <cstdint>
#include <unordered_map>

#include "../errors.h"
#include "byte_order.h"
#include "formats.h"
#include "text_cursor.h"

namespace isoform::meshio {
namespace {

// 80-byte header, uint32 triangle count, then 50 bytes a triangle: normal,
// three corners (12 float32), and a uint16 attribute.
constexpr size_t kHeaderSize = 80;
constexpr size_t kBinaryStart = kHeaderSize + 4;
constexpr size_t kTriangleSize = 50;

// Merges corners whose three floats are equal. Keys are the bit patterns,
// with -0 taken as +0, so that equal means equal as numbers.
class Welder {
 public:
  explicit Welder(Mesh& mesh) : mesh_(mesh) {}
  // A closed triangle mesh has about half as many vertices as triangles
  // (Euler's formula); reserving that spares the table most of its rehashes.
  void expect_triangles(uint64_t count);
  void add_corner(const float point[3]);

 private:
  // Multiplying by the 64-bit golden ratio spreads nearby coordinates, whose
  // bits differ only low in the mantissa, over the whole table.
  struct KeyHash {
    size_t operator()(const std::array<uint32_t, 3>& key) const {
      uint64_t h = key[0];
      h = h * 0x9E3779B97F4A7C15ull ^ key[1];
      h = h * 0x9E3779B97F4A7C15ull ^ key[2];
      return size_t(h ^ (h >> 29));
    }
  };
  Mesh& mesh_;
  std::unordered_map<std::array<uint32_t, 3>, int32_t, KeyHash> index_of_;
};

void Welder::expect_triangles(uint64_t count) {
  index_of_.reserve(size_t(count / 2 + 1));
  mesh_.points.reserve(3 * size_t(count / 2 + 1));
  mesh_.triangles.reserve(3 * size_t(count));
}

void Welder::add_corner(const float point[3]) {
  std::array<uint32_t, 3> key;
  for (size_t k = 0; k < 3; ++k) key[k] = float_bits(point[k] == 0.0f ? 0.0f : point[k]);
  auto [entry, is_new] = index_of_.try_emplace(key, int32_t(mesh_.vertex_count()));
  if (is_new) mesh_.points.insert(mesh_.points.end(), point, point + 3);
  mesh_.triangles.push_back(entry->second);
}

bool finite(const float point[3]) {
  return std::isfinite(point[0]) && std::isfinite(point[1]) && std::isfinite(point[2]);
}

uint64_t binary_triangle_count(std::string_view bytes) {
  return load_little_endian(reinterpret_cast<const unsigned char*>(bytes.data()) + kHeaderSize, 4);
}

// Control bytes other than white space never occur in an ascii STL; a
// binary one has them in its count or its first triangle.
bool looks_like_text(std::string_view bytes) {
  for (unsigned char c : bytes.substr(0, 1024))
    if (c == 127 || (c < 32 && c != '\t' && c != '\n' && c != '\r' && c != '\f' && c != '\v')) return false;
  return true;
}

// A binary header may begin with "solid" too, so the text is taken for ascii
// only when the size does not fit the binary layout and the start reads as
// text; a binary file that lies about its count is then reported as one.
bool is_ascii(std::string_view bytes) {
  if (bytes.size() < 5 || !same_keyword(bytes.substr(0, 5), "solid")) return false;
  if (bytes.size() >= kBinaryStart && bytes.size() == kBinaryStart + kTriangleSize * binary_triangle_count(bytes))
    return false;
  return looks_like_text(bytes);
}

Mesh read_binary(std::string_view bytes, const std::string& path) {
  if (bytes.size() < kBinaryStart) {
    throw FormatError(path + ": too short for an STL file (" + std::to_string(bytes.size()) +
                      " bytes)");
  }
  uint64_t count = binary_triangle_count(bytes);
  uint64_t needed = kBinaryStart + kTriangleSize * count;
  if (bytes.size() < needed) {
    throw FormatError(path + ": binary STL of " + std::to_string(count) + " triangles needs " +
                      std::to_string(needed) + " bytes but the file has " +
                      std::to_string(bytes.size()) + " (truncated?)");
  }
  Mesh mesh;
  Welder welder(mesh);
  welder.expect_triangles(count);
  const auto* record = reinterpret_cast<const unsigned char*>(bytes.data()) + kBinaryStart;
  for (uint64_t t = 0; t < count; ++t, record += kTriangleSize) {
    for (size_t c = 0; c < 3; ++c) {
      float point[3];
      for (size_t k = 0; k < 3; ++k) {
        point[k] = float_from_bits(uint32_t(load_little_endian(record + 12 * (c + 1) + 4 * k, 4)));
      }
      if (!finite(point)) {
        throw FormatError(path + ": triangle " + std::to_string(t) +
                          " has a corner that is not finite");
      }
      welder.add_corner(point);
    }
  }
  return mesh;
}

// solid NAME, then facets "facet normal n n n / outer loop / vertex x y z (3
// times) / endloop / endfacet", then endsolid NAME; several solids may follow
// one another. Keywords are matched without regard to case.
class AsciiStlParser {
 public:
  AsciiStlParser(std::string_view text, const std::string& path)
      : cursor_(text), path_(path), welder_(mesh_) {}
  Mesh run();

 private:
  void read_facet();
  void expect(const char* keyword);
  void read_point(float point[3]);
  [[noreturn]] void fail(const std::string& what) const;

  TextCursor cursor_;
  const std::string& path_;
  Mesh mesh_;
  Welder welder_;
};

Mesh AsciiStlParser::run() {
  for (std::string_view word = cursor_.token(); !word.empty(); word = cursor_.token()) {
    if (!same_keyword(word, "solid")) fail("expected solid, found \"" + std::string(word) + "\"");
    cursor_.next_line();  // the solid's name, which may hold spaces
    for (word = cursor_.token(); !same_keyword(word, "endsolid"); word = cursor_.token()) {
      if (word.empty()) fail("the file ends before endsolid (truncated?)");
      if (!same_keyword(word, "facet")) {
        fail("expected facet or endsolid, found \"" + std::string(word) + "\"");
      }
      read_facet();
    }
    cursor_.next_line();
  }
  return std::move(mesh_);
}

void AsciiStlParser::read_facet() {
  float point[3];
  expect("normal");
  read_point(point);  // recomputed from the corners when needed; only checked here
  expect("outer");
  expect("loop");
  for (int c = 0; c < 3; ++c) {
    expect("vertex");
    read_point(point);
    if (!finite(point)) fail("a vertex is not finite");
    welder_.add_corner(point);
  }
  expect("endloop");
  expect("endfacet");
}

void AsciiStlParser::expect(const char* keyword) {
  std::string_view word = cursor_.token();
  if (word.empty()) fail(std::string("the file ends before ") + keyword + " (truncated?)");
  if (!same_keyword(word, keyword)) {
    fail(std::string("expected ") + keyword + ", found \"" + std::string(word) + "\"");
  }
}

void AsciiStlParser::read_point(float point[3]) {
  for (int k = 0; k < 3; ++k) {
    std::string_view word = cursor_.token();
    if (word.empty()) fail("the file ends inside a facet (truncated?)");
    if (!parse_number(word, point[k])) fail(not_a_float(word));
  }
}

void AsciiStlParser::fail(const std::string& what) const {
  throw FormatError(path_ + ": line " + std::to_string(cursor_.line()) + ": " + what);
}

}  // namespace

Mesh read_stl(std::string_view bytes, const std::string& path) {
  if (is_ascii(bytes)) return AsciiStlParser(bytes, path).run();
  return read_binary(bytes, path);
}

}  // namespace isoform::meshio

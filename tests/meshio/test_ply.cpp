// PLY: round trips, the exact header we write, files in all three encodings
// from other writers (extra elements and properties, polygons, other types),
// and malformed files.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>

#include "libcore/errors.h"
#include "libcore/meshio/meshio.h"
#include "meshio_test_support.h"

namespace isoform::test {
namespace {

template <class T>
void append_big_endian(std::string& bytes, T value) {
  unsigned char raw[sizeof(T)];
  std::memcpy(raw, &value, sizeof(T));
  uint16_t probe = 1;
  bool host_little = *reinterpret_cast<unsigned char*>(&probe) == 1;
  for (size_t i = 0; i < sizeof(T); ++i) {
    bytes.push_back(char(raw[host_little ? sizeof(T) - 1 - i : i]));
  }
}

TEST(Ply, RoundTripKeepsPointsTrianglesNormalsAndParts) {
  TempDir dir;
  Mesh mesh = octahedron();
  save_mesh(mesh, dir.file("octahedron.ply"));
  Mesh loaded = load_mesh(dir.file("octahedron.ply"));
  EXPECT_EQ(loaded.points, mesh.points);
  EXPECT_EQ(loaded.triangles, mesh.triangles);
  EXPECT_EQ(loaded.normals, mesh.normals);
  EXPECT_EQ(loaded.parts, mesh.parts);
  EXPECT_EQ(loaded.part_count, 2);
}

TEST(Ply, HeaderTextIsExact) {
  TempDir dir;
  save_mesh(octahedron(), dir.file("mesh.ply"));
  const std::string expected =
      "ply\n"
      "format binary_little_endian 1.0\n"
      "comment isoform\n"
      "element vertex 6\n"
      "property float x\n"
      "property float y\n"
      "property float z\n"
      "property float nx\n"
      "property float ny\n"
      "property float nz\n"
      "element face 8\n"
      "property list uchar int vertex_indices\n"
      "property int part\n"
      "end_header\n";
  std::string bytes = read_file(dir.file("mesh.ply"));
  ASSERT_EQ(bytes.substr(0, expected.size()), expected);
  EXPECT_EQ(bytes.size(), expected.size() + 6 * 24 + 8 * 17);
  // The first x, 1.6f, in little-endian order whatever the host.
  const unsigned char x_bytes[4] = {0xCD, 0xCC, 0xCC, 0x3F};
  EXPECT_EQ(std::memcmp(bytes.data() + expected.size(), x_bytes, 4), 0);
  // The first face: count 3, then 0, 1, 2.
  const unsigned char face[13] = {3, 0, 0, 0, 0, 1, 0, 0, 0, 2, 0, 0, 0};
  EXPECT_EQ(std::memcmp(bytes.data() + expected.size() + 6 * 24, face, 13), 0);
}

TEST(Ply, WithoutNormalsAndPartsTheHeaderLeavesThemOut) {
  TempDir dir;
  Mesh mesh = octahedron();
  mesh.normals.clear();
  mesh.parts.clear();
  save_mesh(mesh, dir.file("bare.ply"));
  std::string bytes = read_file(dir.file("bare.ply"));
  EXPECT_EQ(bytes.find("nx"), std::string::npos);
  EXPECT_EQ(bytes.find("part"), std::string::npos);
  Mesh loaded = load_mesh(dir.file("bare.ply"));
  EXPECT_EQ(loaded.points, mesh.points);
  EXPECT_EQ(loaded.triangles, mesh.triangles);
  EXPECT_TRUE(loaded.normals.empty());
  EXPECT_TRUE(loaded.parts.empty());
}

TEST(Ply, EmptyMeshRoundTrips) {
  TempDir dir;
  save_mesh(Mesh(), dir.file("empty.ply"));
  Mesh loaded = load_mesh(dir.file("empty.ply"));
  EXPECT_EQ(loaded.vertex_count(), 0u);
  EXPECT_EQ(loaded.triangle_count(), 0u);
}

// A unit cube of quads, with an element before the vertices, one after the
// faces, and vertex properties the mesh has no place for.
TEST(Ply, AsciiQuadsAreFannedAndOtherElementsSkipped) {
  TempDir dir;
  write_file(dir.file("cube.ply"),
             "ply\r\nformat ascii 1.0\r\ncomment hand made\r\n"
             "element material 2\nproperty list uchar float rgba\nproperty uchar shine\n"
             "element vertex 8\nproperty float x\nproperty float y\nproperty float z\n"
             "property uchar red\nproperty float nx\nproperty float ny\nproperty float nz\n"
             "element face 6\nproperty list uchar int vertex_indices\n"
             "element edge 1\nproperty int vertex1\nproperty int vertex2\n"
             "end_header\n"
             "4 1 0 0 1 10\n3 0.5 0.5 0.5 20\n"
             "0 0 0 255 0 0 1\n0.1 0 0 255 0 0 1\n0.1 0.1 0 255 0 0 1\n0 0.1 0 255 0 0 1\n"
             "0 0 0.1 255 0 0 1\n0.1 0 0.1 255 0 0 1\n0.1 0.1 0.1 255 0 0 1\n"
             "0 0.1 0.1 255 0 0 -1\n"
             "4 0 3 2 1\n4 4 5 6 7\n4 0 1 5 4\n4 1 2 6 5\n4 2 3 7 6\n4 3 0 4 7\n"
             "0 1\n");
  Mesh mesh = load_mesh(dir.file("cube.ply"));
  ASSERT_EQ(mesh.vertex_count(), 8u);
  ASSERT_EQ(mesh.triangle_count(), 12u);
  EXPECT_EQ(mesh.points[3], 0.1f);
  EXPECT_EQ(mesh.points[23], 0.1f);
  EXPECT_EQ(std::vector<int32_t>(mesh.triangles.begin(), mesh.triangles.begin() + 6),
            (std::vector<int32_t>{0, 3, 2, 0, 2, 1}));
  ASSERT_EQ(mesh.normals.size(), 24u);
  EXPECT_EQ(mesh.normals[2], 1.0f);
  EXPECT_EQ(mesh.normals[23], -1.0f);
  EXPECT_TRUE(mesh.parts.empty());
}

// Such an element occupies no bytes, so its count costs nothing.
TEST(Ply, ElementWithoutPropertiesIsSkippedAtOnce) {
  TempDir dir;
  write_file(dir.file("hollow.ply"),
             "ply\nformat ascii 1.0\nelement nothing 1000000000000\n"
             "element vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
             "element face 1\nproperty list uchar int vertex_indices\nend_header\n"
             "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
  EXPECT_EQ(load_mesh(dir.file("hollow.ply")).triangles, (std::vector<int32_t>{0, 1, 2}));
}

std::string big_endian_file() {
  std::string bytes =
      "ply\nformat binary_big_endian 1.0\n"
      "element vertex 4\nproperty double x\nproperty float y\nproperty short z\n"
      "property uchar flags\n"
      "element face 2\nproperty uchar intensity\nproperty list ushort uint vertex_index\n"
      "property int part\n"
      "element edge 1\nproperty list uchar int pair\nproperty int weight\n"
      "end_header\n";
  const double xs[4] = {0.5, 2.0, 0.0, -1.0};
  const float ys[4] = {1.25f, 0.0f, 2.0f, 0.1f};
  const int16_t zs[4] = {-3, 0, 0, 300};
  for (int v = 0; v < 4; ++v) {
    append_big_endian(bytes, xs[v]);
    append_big_endian(bytes, ys[v]);
    append_big_endian(bytes, zs[v]);
    append_big_endian(bytes, uint8_t(9));
  }
  append_big_endian(bytes, uint8_t(7));
  append_big_endian(bytes, uint16_t(4));
  for (uint32_t v : {0u, 1u, 2u, 3u}) append_big_endian(bytes, v);
  append_big_endian(bytes, int32_t(2));
  append_big_endian(bytes, uint8_t(8));
  append_big_endian(bytes, uint16_t(3));
  for (uint32_t v : {3u, 2u, 1u}) append_big_endian(bytes, v);
  append_big_endian(bytes, int32_t(0));
  append_big_endian(bytes, uint8_t(2));
  append_big_endian(bytes, int32_t(0));
  append_big_endian(bytes, int32_t(1));
  append_big_endian(bytes, int32_t(5));
  return bytes;
}

TEST(Ply, BigEndianWithMixedTypes) {
  TempDir dir;
  write_file(dir.file("big.ply"), big_endian_file());
  Mesh mesh = load_mesh(dir.file("big.ply"));
  EXPECT_EQ(mesh.points, (std::vector<float>{0.5f, 1.25f, -3, 2, 0, 0, 0, 2, 0, -1, 0.1f, 300}));
  EXPECT_EQ(mesh.triangles, (std::vector<int32_t>{0, 1, 2, 0, 2, 3, 3, 2, 1}));
  EXPECT_EQ(mesh.parts, (std::vector<int32_t>{2, 2, 0}));
  EXPECT_EQ(mesh.part_count, 3);
  EXPECT_TRUE(mesh.normals.empty());
}

TEST(Ply, BigEndianCutInsideTheLastElementIsTruncated) {
  TempDir dir;
  std::string bytes = big_endian_file();
  write_file(dir.file("cut.ply"), bytes.substr(0, bytes.size() - 2));
  std::string message = format_error_of(dir.file("cut.ply"));
  EXPECT_NE(message.find("cut.ply: edge 0: "), std::string::npos) << message;
}

TEST(Ply, TruncatedBinaryNamesFileAndPlace) {
  TempDir dir;
  save_mesh(octahedron(), dir.file("whole.ply"));
  std::string bytes = read_file(dir.file("whole.ply"));
  write_file(dir.file("trunc.ply"), bytes.substr(0, bytes.size() - 5));
  std::string message = format_error_of(dir.file("trunc.ply"));
  EXPECT_EQ(message, dir.file("trunc.ply") + ": face 7: the file ends early (truncated?)");
}

TEST(Ply, FaceIndexOutOfRange) {
  TempDir dir;
  write_file(dir.file("range.ply"),
             "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
             "property float z\nelement face 2\nproperty list uchar int vertex_indices\n"
             "end_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n3 0 1 9\n");
  EXPECT_EQ(format_error_of(dir.file("range.ply")),
            dir.file("range.ply") + ": face 1 refers to vertex 9 but there are 3 vertices");
}

TEST(Ply, BinaryDataBeyondTheHeaderIsRefusedTrailingLineEndsAreNot) {
  TempDir dir;
  save_mesh(octahedron(), dir.file("o.ply"));
  const std::string bytes = read_file(dir.file("o.ply"));
  write_file(dir.file("nl.ply"), bytes + "\r\n");
  EXPECT_EQ(load_mesh(dir.file("nl.ply")).triangles, octahedron().triangles);
  // One face more than the header counts (its 13 bytes).
  write_file(dir.file("more.ply"), bytes + bytes.substr(bytes.size() - 13));
  const std::string message = format_error_of(dir.file("more.ply"));
  EXPECT_NE(message.find("more.ply: holds more data after its last element (face)"), std::string::npos) << message;
}

TEST(Ply, TextFileIsNotPly) {
  TempDir dir;
  write_file(dir.file("notes.ply"), "shopping list\neggs\n");
  std::string message = format_error_of(dir.file("notes.ply"));
  EXPECT_NE(message.find("notes.ply: not a PLY file"), std::string::npos) << message;
}

std::string ascii_triangle(const std::string& header_extra, const std::string& body) {
  return "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n" +
         header_extra + "element face 1\nproperty list uchar int vertex_indices\nend_header\n" +
         body;
}

TEST(Ply, MalformedAsciiFilesAreFormatErrors) {
  TempDir dir;
  struct Case {
    std::string name, text, expected;
  } cases[] = {
      {"no_z.ply", ascii_triangle("", "0 0\n1 0\n0 1\n3 0 1 2\n"), "no scalar property z"},
      {"word.ply", ascii_triangle("property float z\n", "0 0 0\n1 zero 0\n0 1 0\n3 0 1 2\n"),
       "vertex 1: line 11: \"zero\" is not a float"},
      {"big.ply", ascii_triangle("property float z\n", "0 0 0\n1 1e40 0\n0 1 0\n3 0 1 2\n"),
       "vertex 1: line 11: \"1e40\" is beyond the range of a float"},
      {"nan.ply", ascii_triangle("property float z\n", "0 0 0\nnan 0 0\n0 1 0\n3 0 1 2\n"),
       "vertex 1 has x = nan, which is not a finite float"},
      {"two.ply", ascii_triangle("property float z\n", "0 0 0\n1 0 0\n0 1 0\n2 0 1\n"),
       "face 0 has 2 corners; a face needs at least 3"},
      {"short.ply", ascii_triangle("property float z\n", "0 0 0\n1 0 0\n0 1 0\n3 0 1\n"),
       "face 0: the file ends early (truncated?)"},
      {"count.ply", ascii_triangle("property float z\n", "0 0 0\n1 0 0\n0 1 0\n300 0 1 2\n"),
       "\"300\" is not a uchar"},
      {"more.ply", ascii_triangle("property float z\n", "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n3 0 2 1\n"),
       "more.ply: holds more data after its last element (face) than its header declares"},
      {"header.ply", "ply\nformat ascii 1.0\nelement vertex 3\n", "no end_header line"},
      {"type.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty half x\nend_header\n",
       "header line 4: unknown property type \"half\""},
  };
  for (const Case& c : cases) {
    write_file(dir.file(c.name), c.text);
    std::string message = format_error_of(dir.file(c.name));
    EXPECT_NE(message.find(dir.file(c.name) + ": "), std::string::npos) << message;
    EXPECT_NE(message.find(c.expected), std::string::npos) << message;
  }
}

}  // namespace
}  // namespace isoform::test

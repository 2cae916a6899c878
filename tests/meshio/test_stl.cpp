// STL: binary round trips, welding of the per-triangle corners, ascii input,
// and the binary/ascii decision on files that begin with "solid".
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>

#include "libcore/errors.h"
#include "libcore/meshio/meshio.h"
#include "meshio_test_support.h"

namespace isoform::test {
namespace {

float float_at(const std::string& bytes, size_t offset) {
  uint32_t bits = 0;
  for (size_t i = 0; i < 4; ++i) bits |= uint32_t(uint8_t(bytes[offset + i])) << (8 * i);
  float value;
  std::memcpy(&value, &bits, 4);
  return value;
}

// A cube of 12 triangles, each with its own three corners, as STL stores it.
// One corner at the origin is written as -0, which still welds with +0.
Mesh unwelded_cube() {
  const int quads[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4},
                           {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
  const float corners[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                               {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  Mesh mesh;
  for (const auto& quad : quads) {
    for (int corner : {quad[0], quad[1], quad[2], quad[0], quad[2], quad[3]}) {
      mesh.triangles.push_back(int32_t(mesh.vertex_count()));
      mesh.points.insert(mesh.points.end(), corners[corner], corners[corner] + 3);
    }
  }
  mesh.points[3 * 3] = -0.0f;  // triangle 1, corner 0: the origin
  return mesh;
}

TEST(Stl, RoundTripWeldsBackToTheSameMesh) {
  TempDir dir;
  Mesh mesh = octahedron();
  save_mesh(mesh, dir.file("octahedron.stl"));
  Mesh loaded = load_mesh(dir.file("octahedron.stl"));
  EXPECT_EQ(loaded.points, mesh.points);
  EXPECT_EQ(loaded.triangles, mesh.triangles);
  EXPECT_TRUE(loaded.normals.empty());
  EXPECT_TRUE(loaded.parts.empty());
}

TEST(Stl, BinaryLayoutAndFacetNormal) {
  TempDir dir;
  save_mesh(octahedron(), dir.file("mesh.stl"));
  std::string bytes = read_file(dir.file("mesh.stl"));
  ASSERT_EQ(bytes.size(), 84u + 8 * 50);
  EXPECT_EQ(bytes.substr(0, 7), "isoform");
  EXPECT_EQ(bytes.substr(80, 4), std::string("\x08\0\0\0", 4));
  const float expected = float(1 / std::sqrt(3.0));
  for (size_t k = 0; k < 3; ++k) EXPECT_NEAR(float_at(bytes, 84 + 4 * k), expected, 1e-6f);
  EXPECT_EQ(float_at(bytes, 84 + 12), 1.6f);
  EXPECT_EQ(bytes.substr(84 + 48, 2), std::string("\0\0", 2));
}

TEST(Stl, CubeOfTwelveTrianglesWeldsToEightVertices) {
  TempDir dir;
  Mesh cube = unwelded_cube();
  save_mesh(cube, dir.file("cube.stl"));
  Mesh loaded = load_mesh(dir.file("cube.stl"));
  ASSERT_EQ(loaded.vertex_count(), 8u);
  ASSERT_EQ(loaded.triangle_count(), 12u);
  for (size_t c = 0; c < 36; ++c) {
    for (size_t k = 0; k < 3; ++k) {
      EXPECT_EQ(loaded.points[3 * size_t(loaded.triangles[c]) + k], cube.points[3 * c + k]);
    }
  }
}

TEST(Stl, AsciiFacetsShareAnEdge) {
  TempDir dir;
  write_file(dir.file("square.stl"),
             "solid my square part\n"
             "  facet normal 0 0 1\n    outer loop\n"
             "      vertex 0 0 0\n      vertex 1 0 0\n      vertex 1 1 0\n"
             "    endloop\n  endfacet\n"
             "  FACET NORMAL 0 0 1\n    OUTER LOOP\n"
             "      VERTEX 0 0 0\n      VERTEX 1 1 0\n      VERTEX 0 1 0.1e1\n"
             "    ENDLOOP\n  ENDFACET\n"
             "endsolid my square part\n");
  Mesh mesh = load_mesh(dir.file("square.stl"));
  EXPECT_EQ(mesh.points, (std::vector<float>{0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 1}));
  EXPECT_EQ(mesh.triangles, (std::vector<int32_t>{0, 1, 2, 0, 2, 3}));
}

// Some writers start binary headers with "solid"; the size decides.
TEST(Stl, BinaryWhoseHeaderSaysSolid) {
  TempDir dir;
  save_mesh(octahedron(), dir.file("plain.stl"));
  std::string bytes = read_file(dir.file("plain.stl"));
  bytes.replace(0, 11, "solid trick");
  write_file(dir.file("trick.stl"), bytes);
  EXPECT_EQ(load_mesh(dir.file("trick.stl")).triangles, octahedron().triangles);
}

TEST(Stl, MalformedFilesAreFormatErrors) {
  TempDir dir;
  save_mesh(octahedron(), dir.file("whole.stl"));
  std::string binary = read_file(dir.file("whole.stl"));
  // A header that says "solid" and a count beyond the file: a binary file
  // cut short, not an ascii one that lacks endsolid.
  std::string lying = binary;
  lying.replace(0, 10, "solid evil");
  lying[80] = char(0xe8);
  lying[81] = char(0x03);  // 1,000 triangles
  struct Case {
    std::string name, bytes, expected;
  } cases[] = {
      {"cut.stl", binary.substr(0, binary.size() - 1),
       "binary STL of 8 triangles needs 484 bytes but the file has 483 (truncated?)"},
      {"tiny.stl", "abc", "too short for an STL file"},
      {"open.stl", "solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\n",
       "the file ends before vertex (truncated?)"},
      {"typo.stl", "solid x\nfacet normal 0 0 1\nouter lop\n",
       "line 3: expected loop, found \"lop\""},
      {"end.stl", "solid x\n", "the file ends before endsolid"},
      {"solid.stl", lying, "binary STL of 1000 triangles needs 50084 bytes but the file has 484 (truncated?)"},
  };
  for (const Case& c : cases) {
    write_file(dir.file(c.name), c.bytes);
    std::string message = format_error_of(dir.file(c.name));
    EXPECT_EQ(message.rfind(dir.file(c.name) + ": ", 0), 0u) << message;
    EXPECT_NE(message.find(c.expected), std::string::npos) << message;
  }
}

}  // namespace
}  // namespace isoform::test

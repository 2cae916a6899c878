// PLY: the optional vertex properties (colours) and the edge element, as
// bytes on disk, read back by the library's own reader (which skips them).
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>

#include "libcore/errors.h"
#include "libcore/meshio/meshio.h"
#include "meshio_test_support.h"

namespace isoform::test {
namespace {

// A unit triangle with one colour per corner and one loose edge.
Mesh coloured_triangle() {
  Mesh mesh;
  mesh.points = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
  mesh.triangles = {0, 1, 2};
  mesh.colors = {255, 0, 0, 255, 0, 255, 0, 128, 0, 0, 255, 0, 1, 2, 3, 4};
  mesh.edges = {0, 3};
  return mesh;
}

TEST(PlyOptional, ColoursAndEdgesHeaderAndBytes) {
  TempDir dir;
  save_mesh(coloured_triangle(), dir.file("c.ply"));
  const std::string expected =
      "ply\n"
      "format binary_little_endian 1.0\n"
      "comment isoform\n"
      "element vertex 4\n"
      "property float x\n"
      "property float y\n"
      "property float z\n"
      "property uchar red\n"
      "property uchar green\n"
      "property uchar blue\n"
      "property uchar alpha\n"
      "element face 1\n"
      "property list uchar int vertex_indices\n"
      "element edge 1\n"
      "property int vertex1\n"
      "property int vertex2\n"
      "end_header\n";
  const std::string bytes = read_file(dir.file("c.ply"));
  ASSERT_EQ(bytes.substr(0, expected.size()), expected);
  ASSERT_EQ(bytes.size(), expected.size() + 4 * 16 + 13 + 8);
  // Vertex 1's colour follows its three floats: bytes 16 + 12 .. 16 + 15.
  const unsigned char* v1 = reinterpret_cast<const unsigned char*>(bytes.data()) + expected.size() + 16;
  EXPECT_EQ(v1[12], 0);
  EXPECT_EQ(v1[13], 255);
  EXPECT_EQ(v1[14], 0);
  EXPECT_EQ(v1[15], 128);
  // The edge is the last 8 bytes: 0 then 3, little endian.
  const unsigned char* edge = reinterpret_cast<const unsigned char*>(bytes.data()) + bytes.size() - 8;
  EXPECT_EQ(edge[0], 0);
  EXPECT_EQ(edge[4], 3);
  Mesh loaded = load_mesh(dir.file("c.ply"));
  EXPECT_EQ(loaded.points, coloured_triangle().points);
  EXPECT_EQ(loaded.triangles, coloured_triangle().triangles);
}

TEST(PlyOptional, NormalsComeBeforeColours) {
  TempDir dir;
  Mesh mesh = coloured_triangle();
  mesh.normals = {0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1};
  save_mesh(mesh, dir.file("n.ply"));
  const std::string bytes = read_file(dir.file("n.ply"));
  EXPECT_NE(bytes.find("property float nz\nproperty uchar red\n"), std::string::npos);
  EXPECT_EQ(load_mesh(dir.file("n.ply")).normals, mesh.normals);
}

TEST(PlyOptional, WrongColourCountOrEdgeIndexIsRefusedAndNothingWritten) {
  TempDir dir;
  Mesh short_colours = coloured_triangle();
  short_colours.colors.resize(12);
  EXPECT_THROW(save_mesh(short_colours, dir.file("a.ply")), InvalidArgument);
  Mesh bad_edge = coloured_triangle();
  bad_edge.edges = {0, 4};
  EXPECT_THROW(save_mesh(bad_edge, dir.file("b.ply")), InvalidArgument);
  EXPECT_TRUE(dir.entries().empty());
}

TEST(PlyOptional, ObjWritesEdgesAsLines) {
  TempDir dir;
  save_mesh(coloured_triangle(), dir.file("c.obj"));
  const std::string text = read_file(dir.file("c.obj"));
  EXPECT_NE(text.find("\nl 1 4\n"), std::string::npos) << text;
}

}  // namespace
}  // namespace isoform::test

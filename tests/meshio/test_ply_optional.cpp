// PLY: the optional vertex properties (curvature, colours), the edge element
// and double-precision points, as bytes on disk and read back: whatever
// save_mesh writes, load_mesh reads, so that a save of a loaded file gives
// the same bytes.
#include <gtest/gtest.h>

#include <cstdint>
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

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
  EXPECT_EQ(loaded.colors, coloured_triangle().colors);
  EXPECT_EQ(loaded.edges, coloured_triangle().edges);
}

// coloured_triangle with normals and curvature, every value distinct.
Mesh full_triangle() {
  Mesh mesh = coloured_triangle();
  mesh.normals = {0, 0, 1, 0, 0.6f, 0.8f, 0.6f, 0, 0.8f, 1, 0, 0};
  VertexCurvature& c = mesh.curvature;
  for (int v = 0; v < 4; ++v) {
    c.k1.push_back(1.5f + float(v));
    c.k2.push_back(-0.25f * float(v));
    c.mean.push_back(0.5f * (c.k1.back() + c.k2.back()));
    c.gauss.push_back(c.k1.back() * c.k2.back());
    c.absolute.push_back(std::abs(c.k1.back()) + std::abs(c.k2.back()));
    c.d1.insert(c.d1.end(), {1, 0, 0});
    c.d2.insert(c.d2.end(), {0, 1, float(v)});
    c.flags.push_back(uint8_t(v == 2 ? kCurvatureBoundary | kCurvatureWidened : 0));
  }
  c.stats.vertices = 4;
  return mesh;
}

TEST(PlyOptional, CurvatureColoursAndEdgesComeBackAndSaveAgainByteForByte) {
  TempDir dir;
  const Mesh mesh = full_triangle();
  save_mesh(mesh, dir.file("a.ply"));
  const Mesh loaded = load_mesh(dir.file("a.ply"));
  EXPECT_EQ(loaded.normals, mesh.normals);
  EXPECT_EQ(loaded.curvature.k1, mesh.curvature.k1);
  EXPECT_EQ(loaded.curvature.k2, mesh.curvature.k2);
  EXPECT_EQ(loaded.curvature.mean, mesh.curvature.mean);
  EXPECT_EQ(loaded.curvature.gauss, mesh.curvature.gauss);
  EXPECT_EQ(loaded.curvature.absolute, mesh.curvature.absolute);
  EXPECT_EQ(loaded.curvature.d1, mesh.curvature.d1);
  EXPECT_EQ(loaded.curvature.d2, mesh.curvature.d2);
  EXPECT_EQ(loaded.curvature.flags, mesh.curvature.flags);
  EXPECT_EQ(loaded.curvature.stats.vertices, 4);
  EXPECT_EQ(loaded.curvature.stats.boundary, 1);
  EXPECT_EQ(loaded.curvature.stats.widened, 1);
  EXPECT_EQ(loaded.colors, mesh.colors);
  EXPECT_EQ(loaded.edges, mesh.edges);
  EXPECT_TRUE(loaded.precise_points.empty());  // float points stay float
  save_mesh(loaded, dir.file("b.ply"));
  EXPECT_EQ(read_file(dir.file("b.ply")), read_file(dir.file("a.ply")));
}

// An ASCII vertex element with `header` properties and one line per vertex.
std::string ascii_vertices(const std::string& header, const std::vector<std::string>& lines) {
  std::string text = "ply\nformat ascii 1.0\nelement vertex " + std::to_string(lines.size()) + "\n" + header +
                     "element face 1\nproperty list uchar int vertex_indices\nend_header\n";
  for (const std::string& l : lines) text += l + "\n";
  return text + "3 0 1 2\n";
}

TEST(PlyOptional, ColoursWithoutAlphaAreOpaqueAndFloatColoursRunFromZeroToOne) {
  TempDir dir;
  write_file(dir.file("rgb.ply"),
             ascii_vertices("property float x\nproperty float y\nproperty float z\nproperty uchar red\n"
                            "property uchar green\nproperty uchar blue\n",
                            {"0 0 0 10 20 30", "1 0 0 40 50 60", "0 1 0 70 80 90"}));
  EXPECT_EQ(load_mesh(dir.file("rgb.ply")).colors,
            (std::vector<uint8_t>{10, 20, 30, 255, 40, 50, 60, 255, 70, 80, 90, 255}));
  write_file(dir.file("unit.ply"),
             ascii_vertices("property float x\nproperty float y\nproperty float z\nproperty float red\n"
                            "property float green\nproperty float blue\nproperty float alpha\n",
                            {"0 0 0 1 0 0.5 1", "1 0 0 0 1 0 0", "0 1 0 0.2 0.4 0.6 0.8"}));
  EXPECT_EQ(load_mesh(dir.file("unit.ply")).colors,
            (std::vector<uint8_t>{255, 0, 128, 255, 0, 255, 0, 0, 51, 102, 153, 204}));
}

TEST(PlyOptional, AnIncompleteGroupIsSkippedABadValueNamed) {
  TempDir dir;
  // k1 alone is no curvature; red and green alone no colour.
  write_file(dir.file("part.ply"),
             ascii_vertices("property float x\nproperty float y\nproperty float z\nproperty float k1\n"
                            "property uchar red\nproperty uchar green\n",
                            {"0 0 0 1 2 3", "1 0 0 1 2 3", "0 1 0 1 2 3"}));
  const Mesh part = load_mesh(dir.file("part.ply"));
  EXPECT_TRUE(part.curvature.empty());
  EXPECT_TRUE(part.colors.empty());
  EXPECT_EQ(part.points.size(), 9u);
  write_file(dir.file("red.ply"),
             ascii_vertices("property float x\nproperty float y\nproperty float z\nproperty int red\n"
                            "property int green\nproperty int blue\n",
                            {"0 0 0 1 2 3", "1 0 0 1 300 3", "0 1 0 1 2 3"}));
  const std::string error = format_error_of(dir.file("red.ply"));
  EXPECT_NE(error.find("red.ply: vertex 1 has green = 300"), std::string::npos) << error;
}

TEST(PlyOptional, ZeroNormalsAreNoNormalsAndTinyNumbersAreZero) {
  TempDir dir;
  write_file(dir.file("zero.ply"),
             ascii_vertices("property float x\nproperty float y\nproperty float z\nproperty float nx\n"
                            "property float ny\nproperty float nz\n",
                            {"0 0 0 0 0 1", "1 0 0 0 0 0", "0 1 1e-50 0 0 1"}));
  const Mesh zero = load_mesh(dir.file("zero.ply"));
  EXPECT_TRUE(zero.normals.empty());
  EXPECT_EQ(zero.points[8], 0.0f);
  write_file(dir.file("tiny.obj"), "v 0 0 0\nv 1 0 0\nv 0 1 -1e-50\nvn 0 0 1\nf 1//1 2//1 3//1\n");
  const Mesh tiny = load_mesh(dir.file("tiny.obj"));
  EXPECT_EQ(tiny.points[8], 0.0f);
  EXPECT_EQ(tiny.normals.size(), 9u);  // a unit normal is kept
}

TEST(PlyOptional, DoublePointsAreKeptAndWrittenInDoubleWhereFloatWouldMoveThem) {
  TempDir dir;
  // A triangle ten million units from the origin, its sides a few units:
  // float rounding there moves points by up to 0.5.
  const std::string far =
      ascii_vertices("property double x\nproperty double y\nproperty double z\n",
                     {"10000000.125 0.25 0", "10000001.375 0.25 0", "10000000.125 1.5 2.0000001"});
  write_file(dir.file("far.ply"), far);
  const Mesh loaded = load_mesh(dir.file("far.ply"));
  EXPECT_EQ(loaded.precise_points,
            (std::vector<double>{10000000.125, 0.25, 0, 10000001.375, 0.25, 0, 10000000.125, 1.5, 2.0000001}));
  EXPECT_EQ(loaded.points[0], 10000000.0f);
  save_mesh(loaded, dir.file("out.ply"));
  const std::string bytes = read_file(dir.file("out.ply"));
  EXPECT_NE(bytes.find("property double x\nproperty double y\nproperty double z\n"), std::string::npos);
  EXPECT_EQ(load_mesh(dir.file("out.ply")).precise_points, loaded.precise_points);
  save_mesh(loaded, dir.file("out.obj"));
  EXPECT_NE(read_file(dir.file("out.obj")).find("v 10000001.375 0.25 0\n"), std::string::npos);
  // Doubles that floats hold well enough go out as floats.
  write_file(dir.file("near.ply"), ascii_vertices("property double x\nproperty double y\nproperty double z\n",
                                                  {"0 0 0", "1 0 0", "0 1 0.1"}));
  save_mesh(load_mesh(dir.file("near.ply")), dir.file("near_out.ply"));
  EXPECT_NE(read_file(dir.file("near_out.ply")).find("property float x\n"), std::string::npos);
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

// OBJ: round trips (exact, through the shortest float text), the index forms
// of other writers, and when per-vertex normals can be kept.
#include <gtest/gtest.h>

#include "libcore/errors.h"
#include "libcore/meshio/meshio.h"
#include "meshio_test_support.h"

namespace isoform::test {
namespace {

TEST(Obj, RoundTripIsExact) {
  TempDir dir;
  Mesh mesh = octahedron();
  save_mesh(mesh, dir.file("octahedron.obj"));
  Mesh loaded = load_mesh(dir.file("octahedron.obj"));
  EXPECT_EQ(loaded.points, mesh.points);
  EXPECT_EQ(loaded.triangles, mesh.triangles);
  EXPECT_EQ(loaded.normals, mesh.normals);
  EXPECT_TRUE(loaded.parts.empty());
}

TEST(Obj, WrittenText) {
  TempDir dir;
  save_mesh(octahedron(), dir.file("mesh.obj"));
  std::string text = read_file(dir.file("mesh.obj"));
  EXPECT_EQ(text.rfind("# isoform\nv 1.6 -2.25 3\n", 0), 0u) << text;
  EXPECT_NE(text.find("\nvn 1 0 0\n"), std::string::npos) << text;
  EXPECT_NE(text.find("\nf 1//1 2//2 3//3\n"), std::string::npos) << text;
}

TEST(Obj, WithoutNormalsFacesHaveBareIndices) {
  TempDir dir;
  Mesh mesh = octahedron();
  mesh.normals.clear();
  save_mesh(mesh, dir.file("bare.obj"));
  EXPECT_NE(read_file(dir.file("bare.obj")).find("\nf 1 2 3\n"), std::string::npos);
  Mesh loaded = load_mesh(dir.file("bare.obj"));
  EXPECT_EQ(loaded.points, mesh.points);
  EXPECT_EQ(loaded.triangles, mesh.triangles);
  EXPECT_TRUE(loaded.normals.empty());
}

// A square as one quad with relative indices and v/vt/vn corners, among
// lines that do not describe the surface.
TEST(Obj, NegativeIndicesAndTextureCoordinates) {
  TempDir dir;
  write_file(dir.file("quad.obj"),
             "# exported\nmtllib quad.mtl\no Quad\n"
             "v 0 0 0\nv 1 0 0\nv 1 1 0 1.0\nv 0 1 0\n"
             "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
             "vn 0 0 1\n"
             "usemtl skin\ns off\n"
             "f -4/-4/-1 -3/-3/-1 -2/-2/-1 -1/-1/-1 # the quad\n");
  Mesh mesh = load_mesh(dir.file("quad.obj"));
  EXPECT_EQ(mesh.points, (std::vector<float>{0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0}));
  EXPECT_EQ(mesh.triangles, (std::vector<int32_t>{0, 1, 2, 0, 2, 3}));
  EXPECT_EQ(mesh.normals, (std::vector<float>{0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1}));
}

TEST(Obj, AllCornerFormsMix) {
  TempDir dir;
  write_file(dir.file("forms.obj"),
             "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nvt 0 0\nvn 0 0 1\nvn 0 0 1\n"
             "f 1 2/1 3/1/1\nf 1//2 4 2/1/2\n");
  Mesh mesh = load_mesh(dir.file("forms.obj"));
  EXPECT_EQ(mesh.triangles, (std::vector<int32_t>{0, 1, 2, 0, 3, 1}));
  // Vertex 4 never gets a normal, so none are kept.
  EXPECT_TRUE(mesh.normals.empty());
}

TEST(Obj, SameNormalValueUnderTwoIndicesIsConsistent) {
  TempDir dir;
  write_file(dir.file("repeat.obj"),
             "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nvn 0 0 1\nvn 0 0 1\n"
             "f 1//1 2//1 3//1\nf 2//2 4//2 3//2\n");
  EXPECT_EQ(load_mesh(dir.file("repeat.obj")).normals.size(), 12u);
}

TEST(Obj, CreaseNormalsAreDropped) {
  TempDir dir;
  write_file(dir.file("crease.obj"),
             "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nvn 0 0 1\nvn 0 1 0\n"
             "f 1//1 2//1 3//1\nf 1//2 4//2 2//2\n");
  Mesh mesh = load_mesh(dir.file("crease.obj"));
  EXPECT_EQ(mesh.triangle_count(), 2u);
  EXPECT_TRUE(mesh.normals.empty());
}

TEST(Obj, MalformedFilesAreFormatErrors) {
  TempDir dir;
  struct Case {
    std::string name, text, expected;
  } cases[] = {
      {"range.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n",
       "line 4: a face refers to vertex 9 but 3 are defined before it"},
      {"back.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf -1 -2 -4\n", "vertex -4 but 3 are defined"},
      {"zero.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n", "\"0\" is not a valid vertex index"},
      {"normal.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1//1 2 3\n", "refers to normal 1 but 0"},
      {"short.obj", "v 0 0 0\nv 1 0\n", "line 2: v needs three numbers"},
      {"word.obj", "v 0 zero 0\n", "line 1: \"zero\" is not a number"},
      {"big.obj", "v 0 1e40 0\n", "line 1: \"1e40\" is beyond the range of a float"},
      {"inf.obj", "v 0 0 0\nv 0 inf 0\n", "line 2: v has a value that is not finite"},
      {"edge.obj", "v 0 0 0\nv 1 0 0\nf 1 2\n", "a face has 2 corners"},
  };
  for (const Case& c : cases) {
    write_file(dir.file(c.name), c.text);
    std::string message = format_error_of(dir.file(c.name));
    EXPECT_EQ(message.rfind(dir.file(c.name) + ": ", 0), 0u) << message;
    EXPECT_NE(message.find(c.expected), std::string::npos) << message;
  }
}

}  // namespace
}  // namespace isoform::test

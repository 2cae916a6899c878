// save_mesh and load_mesh around the formats: atomic replacement, failures
// that must leave the file system as it was, and the choice by extension.
#include <gtest/gtest.h>

#include <filesystem>

#include "libcore/errors.h"
#include "libcore/meshio/atomic_file.h"
#include "libcore/meshio/meshio.h"
#include "meshio_test_support.h"

namespace isoform::test {
namespace {

namespace fs = std::filesystem;

TEST(Atomic, SaveReplacesAnExistingFileAndLeavesNoTemporary) {
  TempDir dir;
  write_file(dir.file("mesh.ply"), "old content");
  save_mesh(octahedron(), dir.file("mesh.ply"));
  EXPECT_EQ(load_mesh(dir.file("mesh.ply")).triangles, octahedron().triangles);
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"mesh.ply"});
}

TEST(Atomic, MissingDirectoryIsAnIoErrorAndCreatesNothing) {
  TempDir dir;
  std::string path = dir.file("absent/mesh.ply");
  try {
    save_mesh(octahedron(), path);
    ADD_FAILURE() << "saved into a missing directory";
  } catch (const IoError& e) {
    EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("No such file or directory"), std::string::npos)
        << e.what();
  }
  EXPECT_TRUE(dir.entries().empty());
}

// The rename cannot replace a directory: what was there stays, and the
// temporary file is gone.
TEST(Atomic, FailedRenameLeavesTheTargetAndNoTemporary) {
  for (const char* name : {"taken.ply", "taken.obj", "taken.stl"}) {
    TempDir dir;
    fs::create_directory(dir.file(name));
    write_file(dir.file(name) + "/inside.txt", "keep me");
    EXPECT_THROW(save_mesh(octahedron(), dir.file(name)), IoError) << name;
    EXPECT_TRUE(fs::is_directory(dir.file(name)));
    EXPECT_EQ(read_file(dir.file(name) + "/inside.txt"), "keep me");
    EXPECT_EQ(dir.entries(), std::vector<std::string>{name});
  }
}

// A cancel set before or during the write: Cancelled, the old file as it
// was, no temporary file.
TEST(Atomic, ACancelledSaveLeavesTheTargetAndNoTemporary) {
  TempDir dir;
  write_file(dir.file("mesh.ply"), "old content");
  isoform_progress sink{};
  sink.cancel = 1;
  EXPECT_THROW(save_mesh(octahedron(), dir.file("mesh.ply"), Progress(&sink)), Cancelled);
  EXPECT_EQ(read_file(dir.file("mesh.ply")), "old content");
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"mesh.ply"});
  sink.cancel = 0;
  save_mesh(octahedron(), dir.file("mesh.ply"), Progress(&sink));
  EXPECT_EQ(load_mesh(dir.file("mesh.ply")).triangles, octahedron().triangles);
}

TEST(Atomic, ACancelBetweenBuffersStopsTheWrite) {
  TempDir dir;
  int asked = 0;
  {
    meshio::AtomicFile file(dir.file("big.bin"), [&asked] { return ++asked >= 3; });
    const std::string chunk(300000, 'x');
    try {
      for (int k = 0; k < 20; ++k) file.write(chunk);
      file.commit();
      ADD_FAILURE() << "the write was not cancelled";
    } catch (const Cancelled& e) {
      EXPECT_NE(std::string(e.what()).find("big.bin"), std::string::npos) << e.what();
    }
    EXPECT_EQ(asked, 3);  // asked once per full buffer: stopped at the third
  }
  EXPECT_TRUE(dir.entries().empty());
}

TEST(Atomic, InvalidMeshIsRefusedBeforeTouchingTheFile) {
  TempDir dir;
  write_file(dir.file("mesh.obj"), "old content");
  Mesh mesh = octahedron();
  mesh.triangles[5] = 6;
  EXPECT_THROW(save_mesh(mesh, dir.file("mesh.obj")), InvalidArgument);
  mesh = octahedron();
  mesh.parts.pop_back();
  EXPECT_THROW(save_mesh(mesh, dir.file("mesh.obj")), InvalidArgument);
  mesh = octahedron();
  mesh.normals.resize(3);
  EXPECT_THROW(save_mesh(mesh, dir.file("mesh.obj")), InvalidArgument);
  EXPECT_EQ(read_file(dir.file("mesh.obj")), "old content");
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"mesh.obj"});
}

TEST(Dispatch, UnknownExtensionIsInvalidArgument) {
  TempDir dir;
  EXPECT_THROW(save_mesh(octahedron(), dir.file("mesh.off")), InvalidArgument);
  EXPECT_THROW(save_mesh(octahedron(), dir.file("mesh")), InvalidArgument);
  write_file(dir.file("mesh.off"), "OFF\n");
  EXPECT_THROW(load_mesh(dir.file("mesh.off")), InvalidArgument);
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"mesh.off"});
}

TEST(Dispatch, ExtensionCaseDoesNotMatter) {
  TempDir dir;
  save_mesh(octahedron(), dir.file("MESH.PLY"));
  save_mesh(octahedron(), dir.file("mesh.Obj"));
  EXPECT_EQ(read_file(dir.file("MESH.PLY")).rfind("ply\n", 0), 0u);
  EXPECT_EQ(load_mesh(dir.file("mesh.Obj")).points, octahedron().points);
}

TEST(Dispatch, MissingFileIsAnIoErrorNamingIt) {
  TempDir dir;
  try {
    load_mesh(dir.file("nothing.stl"));
    ADD_FAILURE() << "loaded a missing file";
  } catch (const IoError& e) {
    EXPECT_NE(std::string(e.what()).find(dir.file("nothing.stl")), std::string::npos);
  }
}

TEST(Dispatch, DirectoryIsAnIoError) {
  TempDir dir;
  fs::create_directory(dir.file("folder.ply"));
  EXPECT_THROW(load_mesh(dir.file("folder.ply")), IoError);
}

}  // namespace
}  // namespace isoform::test

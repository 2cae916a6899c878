// Shared pieces of the meshio tests: a temporary directory per test, a small
// mesh made in code, and whole-file helpers.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "libcore/mesh.h"

namespace isoform::test {

// A fresh directory under the system's temporary directory, removed with
// everything in it when the test ends.
class TempDir {
 public:
  TempDir();
  ~TempDir();
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;

  // The path of name inside the directory.
  std::string file(const std::string& name) const { return (dir_ / name).string(); }
  // Names of the entries in the directory, sorted.
  std::vector<std::string> entries() const;

 private:
  std::filesystem::path dir_;
};

// A regular octahedron of radius 1.5 around (0.1, -2.25, 3), outward
// counter-clockwise triangles, unit normals, the upper four triangles in
// part 0 and the lower four in part 1. Its vertices first appear in the
// triangle list in index order, so a welded STL gives them back in order.
Mesh octahedron();

void write_file(const std::string& path, const std::string& bytes);
std::string read_file(const std::string& path);

// The message of the FormatError that load_mesh(path) throws; a test failure
// if it throws nothing or something else.
std::string format_error_of(const std::string& path);

}  // namespace isoform::test

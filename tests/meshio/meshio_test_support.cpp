#include "meshio_test_support.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <fstream>
#include <iterator>
#include <random>

#include "libcore/errors.h"
#include "libcore/meshio/meshio.h"

namespace isoform::test {

TempDir::TempDir() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  std::random_device random;
  std::string name = std::string("isoform_meshio_") + info->test_suite_name() + "_" +
                     info->name() + "_" + std::to_string(::getpid()) + "_" +
                     std::to_string(random());
  dir_ = std::filesystem::temp_directory_path() / name;
  std::filesystem::create_directories(dir_);
}

TempDir::~TempDir() {
  std::error_code ignored;
  std::filesystem::remove_all(dir_, ignored);
}

std::vector<std::string> TempDir::entries() const {
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(dir_)) {
    names.push_back(entry.path().filename().string());
  }
  std::sort(names.begin(), names.end());
  return names;
}

Mesh octahedron() {
  const float centre[3] = {0.1f, -2.25f, 3.0f};
  const float radius = 1.5f;
  // +x, +y, +z, -x, -y, -z
  const float directions[6][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1},
                                  {-1, 0, 0}, {0, -1, 0}, {0, 0, -1}};
  Mesh mesh;
  for (const auto& d : directions) {
    for (int k = 0; k < 3; ++k) {
      mesh.points.push_back(centre[k] + radius * d[k]);
      mesh.normals.push_back(d[k]);
    }
  }
  mesh.triangles = {0, 1, 2, 1, 3, 2, 3, 4, 2, 4, 0, 2,
                    1, 0, 5, 3, 1, 5, 4, 3, 5, 0, 4, 5};
  mesh.parts = {0, 0, 0, 0, 1, 1, 1, 1};
  mesh.part_count = 2;
  return mesh;
}

void write_file(const std::string& path, const std::string& bytes) {
  std::ofstream out(path, std::ios::binary);
  out.write(bytes.data(), std::streamsize(bytes.size()));
  ASSERT_TRUE(out.good()) << path;
}

std::string read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

std::string format_error_of(const std::string& path) {
  try {
    load_mesh(path);
  } catch (const FormatError& e) {
    return e.what();
  } catch (const std::exception& e) {
    ADD_FAILURE() << "expected a FormatError from " << path << ", got: " << e.what();
    return "";
  }
  ADD_FAILURE() << "expected a FormatError from " << path << ", it loaded";
  return "";
}

}  // namespace isoform::test

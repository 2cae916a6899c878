// Helpers shared by the vdbio tests: the real-data folder, scratch
// directories, expected error messages and odd files written by OpenVDB.
#pragma once

#include <gtest/gtest.h>
#include <openvdb/openvdb.h>
#include <unistd.h>

#include <atomic>
#include <exception>
#include <filesystem>
#include <string>

namespace isoform::vdbio::test {

// A file of the shared real-data folder. CI always has the folder, so a
// missing file fails the test (it is not skipped).
inline std::string data_file(const std::string& name) {
  const std::string path = std::string(ISOFORM_SHARED_DATA) + "/" + name;
  EXPECT_TRUE(std::filesystem::is_regular_file(path)) << "missing test data: " << path;
  return path;
}

// A fresh directory under the system's temporary folder, removed with all
// it holds when the test ends.
class TempDir {
 public:
  TempDir() {
    static std::atomic<int> counter{0};
    path_ = std::filesystem::temp_directory_path() /
            ("isoform-vdbio-" + std::to_string(::getpid()) + "-" + std::to_string(counter++));
    std::filesystem::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;

  std::string file(const std::string& name) const { return (path_ / name).string(); }
  const std::filesystem::path& path() const { return path_; }
  size_t entry_count() const {
    size_t n = 0;
    for (const auto& entry : std::filesystem::directory_iterator(path_)) n += entry.exists();
    return n;
  }

 private:
  std::filesystem::path path_;
};

// The message of the exception of type E that body throws; a test failure
// (and "") if it throws nothing or something else.
template <class E, class Body>
std::string error_of(Body&& body) {
  try {
    body();
  } catch (const E& e) {
    return e.what();
  } catch (const std::exception& e) {
    ADD_FAILURE() << "unexpected exception type: " << e.what();
    return "";
  }
  ADD_FAILURE() << "no exception thrown";
  return "";
}

// Writes grids to path with OpenVDB itself, for tests that need odd files.
inline void write_grids(const std::string& path, const openvdb::GridPtrVec& grids) {
  openvdb::initialize();
  openvdb::io::File(path).write(grids);
}

}  // namespace isoform::vdbio::test

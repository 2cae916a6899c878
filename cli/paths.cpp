// Output path checks and the output folder of `pipeline`.
#include "paths.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <system_error>

#include "cli.h"

namespace fs = std::filesystem;

namespace isoform::cli {
namespace {

std::string join_extensions(const std::vector<std::string>& extensions) {
  std::string text;
  for (size_t i = 0; i < extensions.size(); ++i) {
    if (i > 0) text += i + 1 == extensions.size() ? " or " : ", ";
    text += extensions[i];
  }
  return text;
}

// equivalent() compares device and inode, so a symlink or a hard link to the
// input counts as the input; it reports an error (not equal) when either
// path does not exist, and a missing output cannot be the input.
bool same_file(const std::string& a, const std::string& b) {
  std::error_code error;
  return fs::equivalent(a, b, error);
}

void check_folder(const std::string& output) {
  const fs::path folder = fs::path(output).parent_path();
  if (folder.empty()) return;
  std::error_code error;
  const fs::file_status status = fs::status(folder, error);
  if (!fs::exists(status))
    throw Failure(output + ": cannot write: folder '" + folder.string() + "' does not exist");
  if (!fs::is_directory(status))
    throw Failure(output + ": cannot write: '" + folder.string() + "' is not a folder");
}

}  // namespace

std::string lower_extension(const std::string& path) {
  std::string extension = fs::path(path).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  return extension;
}

void check_output_path(const std::string& input, const std::string& output,
                       const std::vector<std::string>& extensions) {
  if (same_file(input, output))
    throw Failure("output " + output + " is the input file " + input +
                  "; refusing to overwrite the input, choose another output path");
  const std::string extension = lower_extension(output);
  if (std::find(extensions.begin(), extensions.end(), extension) == extensions.end()) {
    const std::string what = extension.empty() ? "no extension" : "extension '" + extension + "'";
    throw Failure(output + ": unknown output format (" + what + "); use " +
                  join_extensions(extensions));
  }
  check_folder(output);
}

void make_output_folder(const std::string& dir) {
  std::error_code error;
  fs::create_directories(dir, error);
  if (error) throw Failure(dir + ": cannot create the output folder: " + error.message());
  if (!fs::is_directory(dir)) throw Failure(dir + ": exists and is not a folder");
}

}  // namespace isoform::cli

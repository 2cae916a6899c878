// A file that appears at its path complete or not at all. Bytes go to a
// temporary file beside the path (same directory, so the final rename stays
// on one file system and is atomic); commit() flushes it to disk and renames
// it over the path. Until then the path is untouched, and a destroyed,
// uncommitted AtomicFile removes its temporary file.
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace isoform::meshio {

class AtomicFile {
 public:
  // Creates PATH.tmp-<random> in path's directory. Throws IoError. With
  // `cancelled`, each buffer written and the rename first ask it, and throw
  // Cancelled when it says yes (the temporary file is then removed).
  explicit AtomicFile(const std::string& path, std::function<bool()> cancelled = {});
  ~AtomicFile();
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  // Appends bytes (buffered). Throws IoError.
  void write(const void* data, size_t size);
  void write(std::string_view text) { write(text.data(), text.size()); }

  // Flushes, fsyncs, closes and renames the temporary file over the path.
  // Throws IoError; the destructor then removes the temporary file.
  void commit();

 private:
  void flush();
  void check_cancel() const;
  [[noreturn]] void fail(const std::string& action, int error) const;

  std::string path_;
  std::string temp_path_;
  int fd_ = -1;
  bool committed_ = false;
  std::vector<unsigned char> buffer_;
  std::function<bool()> cancelled_;
};

}  // namespace isoform::meshio

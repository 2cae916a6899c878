// Bounded reads from a file whose every length field is suspect: a read or
// skip that would pass the end of the file (or of a region within it) fails
// with the file's name, what was being read and where, and nothing is ever
// allocated from a length the file gives.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace isoform::vdbio {

class ByteCursor {
 public:
  // Throws IoError if the file is missing or unreadable. `failure` begins
  // every FormatError message after the path, e.g. "truncated or damaged
  // OpenVDB file".
  ByteCursor(const std::string& path, std::string failure);
  ~ByteCursor();
  ByteCursor(const ByteCursor&) = delete;
  ByteCursor& operator=(const ByteCursor&) = delete;

  const std::string& path() const { return path_; }
  uint64_t size() const { return size_; }
  uint64_t pos() const { return pos_; }
  // Reads end here (at most the file's size) until the next limit() call.
  void limit(uint64_t end);
  uint64_t end() const { return end_; }
  uint64_t remaining() const { return end_ - pos_; }

  // Throws FormatError "<path>: <failure> (<what> at byte <pos> ...)" when
  // fewer than n bytes remain before the end.
  void need(uint64_t n, const char* what) const;
  void read(void* out, size_t n, const char* what);
  void skip(uint64_t n, const char* what);
  void seek(uint64_t pos, const char* what);
  template <class T>
  T get(const char* what) {
    T value;
    read(&value, sizeof value, what);
    return value;
  }
  // A uint32 length, then that many bytes (checked against what remains).
  std::string string(const char* what);

  // Throws FormatError "<path>: <failure> (<problem>)".
  [[noreturn]] void fail(const std::string& problem) const;

 private:
  void fill(uint64_t pos, size_t n, void* out);

  std::string path_, failure_;
  int fd_ = -1;
  uint64_t size_ = 0, pos_ = 0, end_ = 0;
  // A window of the file kept in memory: most reads are a few bytes.
  std::vector<unsigned char> window_;
  uint64_t window_pos_ = 0;
  size_t window_size_ = 0;
};

}  // namespace isoform::vdbio

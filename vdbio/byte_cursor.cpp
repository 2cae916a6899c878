// Bounded reads from an untrusted file (see byte_cursor.h).
#include "byte_cursor.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>

#include "input_file.h"
#include "libcore/errors.h"

namespace isoform::vdbio {

namespace {
constexpr size_t kWindow = size_t(1) << 16;
}

ByteCursor::ByteCursor(const std::string& path, std::string failure)
    : path_(path), failure_(std::move(failure)) {
  require_input_file(path);
  fd_ = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd_ < 0) throw IoError(path + ": cannot be read (" + std::strerror(errno) + ")");
  struct stat st;
  if (::fstat(fd_, &st) != 0) {
    const int e = errno;
    ::close(fd_);
    throw IoError(path + ": cannot get its size (" + std::strerror(e) + ")");
  }
  size_ = end_ = uint64_t(st.st_size);
  window_.resize(kWindow);
}

ByteCursor::~ByteCursor() {
  if (fd_ >= 0) ::close(fd_);
}

void ByteCursor::limit(uint64_t end) { end_ = std::min(end, size_); }

void ByteCursor::fail(const std::string& problem) const {
  throw FormatError(path_ + ": " + failure_ + " (" + problem + ")");
}

void ByteCursor::need(uint64_t n, const char* what) const {
  if (n <= end_ - pos_) return;
  fail(std::string(what) + " at byte " + std::to_string(pos_) + " needs " + std::to_string(n) +
       " bytes but " + std::to_string(end_ - pos_) + " remain" +
       (end_ == size_ ? " in the file" : " in its grid"));
}

void ByteCursor::fill(uint64_t pos, size_t n, void* out) {
  auto* dst = static_cast<unsigned char*>(out);
  while (n > 0) {
    if (pos < window_pos_ || pos >= window_pos_ + window_size_) {
      const ssize_t got = ::pread(fd_, window_.data(), kWindow, off_t(pos));
      if (got < 0 && errno == EINTR) continue;
      if (got < 0) throw IoError(path_ + ": cannot be read (" + std::strerror(errno) + ")");
      // The file shrank after it was measured.
      if (got == 0) fail("the file ends at byte " + std::to_string(pos) + ", before its stated size");
      window_pos_ = pos;
      window_size_ = size_t(got);
    }
    const size_t at = size_t(pos - window_pos_), take = std::min(n, window_size_ - at);
    std::memcpy(dst, window_.data() + at, take);
    dst += take;
    pos += take;
    n -= take;
  }
}

void ByteCursor::read(void* out, size_t n, const char* what) {
  need(n, what);
  fill(pos_, n, out);
  pos_ += n;
}

void ByteCursor::skip(uint64_t n, const char* what) {
  need(n, what);
  pos_ += n;
}

void ByteCursor::seek(uint64_t pos, const char* what) {
  if (pos > end_)
    fail(std::string(what) + " at byte " + std::to_string(pos) + " lies past the end (byte " +
         std::to_string(end_) + ")");
  pos_ = pos;
}

std::string ByteCursor::string(const char* what) {
  const uint32_t n = get<uint32_t>(what);
  need(n, what);  // before the allocation, not after
  std::string s(n, '\0');
  read(s.data(), n, what);
  return s;
}

}  // namespace isoform::vdbio

// Atomic saves with POSIX calls, so that each step (exclusive create, fsync,
// rename) is explicit and its failure reported with errno.
#include "atomic_file.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <filesystem>
#include <random>
#include <system_error>
#include <utility>

#include "../errors.h"

namespace isoform::meshio {
namespace {

// Large enough that writes cost few system calls, small beside a mesh.
constexpr size_t kBufferSize = size_t(1) << 20;
// O_EXCL collisions on 64 random bits mean something else is wrong; stop.
constexpr int kCreateAttempts = 8;

std::string error_text(int error) { return std::generic_category().message(error); }

std::string random_suffix() {
  std::random_device device;
  std::uniform_int_distribution<unsigned long long> digits;
  char text[17];
  std::snprintf(text, sizeof text, "%016llx", digits(device));
  return text;
}

// Writes everything, resuming after signals and short writes. Returns 0 or
// an errno value.
int write_all(int fd, const unsigned char* data, size_t size) {
  while (size > 0) {
    ssize_t done = ::write(fd, data, size);
    if (done < 0) {
      if (errno == EINTR) continue;
      return errno;
    }
    data += done;
    size -= static_cast<size_t>(done);
  }
  return 0;
}

// Makes the rename itself durable. Best effort: the file is already complete
// under its name, and some file systems refuse fsync on directories, so a
// failure here is not worth reporting a failed save.
void sync_directory_of(const std::string& path) {
  std::filesystem::path dir = std::filesystem::path(path).parent_path();
  if (dir.empty()) dir = ".";
  int fd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) return;
  ::fsync(fd);
  ::close(fd);
}

}  // namespace

AtomicFile::AtomicFile(const std::string& path, std::function<bool()> cancelled)
    : path_(path), cancelled_(std::move(cancelled)) {
  int error = 0;
  for (int attempt = 0; attempt < kCreateAttempts; ++attempt) {
    temp_path_ = path + ".tmp-" + random_suffix();
    // Mode 0666 lets the umask decide, as for any newly created file.
    fd_ = ::open(temp_path_.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd_ >= 0) break;
    error = errno;
    if (error != EEXIST) break;
  }
  if (fd_ < 0) {
    throw IoError("cannot create a temporary file beside " + path + ": " + error_text(error));
  }
  buffer_.reserve(kBufferSize);
}

AtomicFile::~AtomicFile() {
  if (fd_ >= 0) ::close(fd_);
  if (!committed_) ::unlink(temp_path_.c_str());
}

void AtomicFile::write(const void* data, size_t size) {
  const auto* bytes = static_cast<const unsigned char*>(data);
  if (buffer_.size() + size > kBufferSize) flush();
  if (size >= kBufferSize) {
    if (int error = write_all(fd_, bytes, size)) fail("write", error);
    return;
  }
  buffer_.insert(buffer_.end(), bytes, bytes + size);
}

void AtomicFile::check_cancel() const {
  if (cancelled_ && cancelled_()) throw Cancelled("writing " + path_ + " was cancelled");
}

void AtomicFile::flush() {
  check_cancel();
  if (int error = write_all(fd_, buffer_.data(), buffer_.size())) fail("write", error);
  buffer_.clear();
}

void AtomicFile::commit() {
  flush();
  if (::fsync(fd_) != 0) fail("sync", errno);
  int fd = fd_;
  fd_ = -1;
  // close can report a deferred write error (NFS), so it is checked too.
  if (::close(fd) != 0) fail("close", errno);
  check_cancel();
  if (std::rename(temp_path_.c_str(), path_.c_str()) != 0) {
    int error = errno;
    throw IoError("cannot rename " + temp_path_ + " to " + path_ + ": " + error_text(error));
  }
  committed_ = true;
  sync_directory_of(path_);
}

void AtomicFile::fail(const std::string& action, int error) const {
  throw IoError("cannot " + action + " " + path_ + " (temporary file " + temp_path_ +
                "): " + error_text(error));
}

}  // namespace isoform::meshio

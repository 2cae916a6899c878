// POSIX reads, so that errors carry errno (a directory, a missing file, a
// permission) rather than a stream's bare failbit.
#include "file_bytes.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <system_error>

#include "../errors.h"

namespace isoform::meshio {
namespace {

// The first buffer when the size is not known up front (a pipe).
constexpr size_t kFirstBuffer = size_t(1) << 20;

[[noreturn]] void fail(const char* action, const std::string& path, int error) {
  throw IoError(std::string("cannot ") + action + " " + path + ": " +
                std::generic_category().message(error));
}

// Owns the descriptor so that every exit closes it.
struct Descriptor {
  int fd;
  ~Descriptor() { ::close(fd); }
};

}  // namespace

std::string read_file_bytes(const std::string& path) {
  int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) fail("open", path, errno);
  Descriptor descriptor{fd};
  struct stat info {};
  // The size is a hint only: pipes report 0 and files may change meanwhile.
  // One byte more lets the read that finds the end happen without growing.
  size_t hint = ::fstat(fd, &info) == 0 && info.st_size > 0 ? size_t(info.st_size) : 0;
  std::string bytes(hint > 0 ? hint + 1 : kFirstBuffer, '\0');
  size_t used = 0;
  for (;;) {
    if (used == bytes.size()) bytes.resize(2 * bytes.size());
    ssize_t done = ::read(fd, &bytes[used], bytes.size() - used);
    if (done < 0) {
      if (errno == EINTR) continue;
      fail("read", path, errno);
    }
    if (done == 0) break;
    used += static_cast<size_t>(done);
  }
  bytes.resize(used);
  return bytes;
}

}  // namespace isoform::meshio

// Checks on an input file before a format reader sees it.
#include "input_file.h"

#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "libcore/errors.h"

namespace isoform::vdbio {

namespace fs = std::filesystem;

void require_input_file(const std::string& path) {
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (!fs::exists(status)) throw IoError(path + ": no such file");
  if (!fs::is_regular_file(status)) throw IoError(path + ": not a regular file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw IoError(path + ": cannot be read (" + std::strerror(errno) + ")");
}

std::uintmax_t input_file_size(const std::string& path) {
  require_input_file(path);
  std::error_code ec;
  const std::uintmax_t size = fs::file_size(path, ec);
  if (ec) throw IoError(path + ": cannot get its size (" + ec.message() + ")");
  return size;
}

std::string read_prefix(const std::string& path, size_t n) {
  require_input_file(path);
  std::ifstream in(path, std::ios::binary);
  std::string bytes(n, '\0');
  in.read(bytes.data(), std::streamsize(n));
  if (in.bad()) throw IoError(path + ": cannot be read");
  bytes.resize(size_t(in.gcount()));
  return bytes;
}

uint64_t default_memory_budget() {
  const long pages = ::sysconf(_SC_PHYS_PAGES), page = ::sysconf(_SC_PAGE_SIZE);
  if (pages <= 0 || page <= 0) return uint64_t(4) << 30;
  return uint64_t(pages) * uint64_t(page) / 2;
}

namespace {
std::atomic<uint64_t> budget_set{0};
}

uint64_t memory_budget() {
  const uint64_t bytes = budget_set.load(std::memory_order_relaxed);
  return bytes ? bytes : default_memory_budget();
}

void set_memory_budget(uint64_t bytes) { budget_set.store(bytes, std::memory_order_relaxed); }

std::string size_text(uint64_t bytes) {
  static const char* const units[] = {"KiB", "MiB", "GiB", "TiB"};
  double value = double(bytes) / 1024;
  int unit = 0;
  for (; unit < 3 && value >= 1024; ++unit) value /= 1024;
  char text[48];
  std::snprintf(text, sizeof text, "%.1f %s", value, units[unit]);
  return text;
}

}  // namespace isoform::vdbio

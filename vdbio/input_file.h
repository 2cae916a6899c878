// Checks on an input file before a format reader sees it, so that a missing
// or unreadable file gives an IoError naming it, whatever the format.
#pragma once

#include <cstdint>
#include <string>

namespace isoform::vdbio {

// Throws IoError "PATH: no such file" (or not a regular file, or unreadable).
void require_input_file(const std::string& path);

// Size of the file in bytes; throws IoError if it cannot be found.
std::uintmax_t input_file_size(const std::string& path);

// The first n bytes of the file (fewer if it is shorter); throws IoError if
// it cannot be read.
std::string read_prefix(const std::string& path, size_t n);

// The most memory one file's data may take once decoded: half the
// machine's physical memory. A file whose sizes claim more is refused
// before anything is allocated for it.
uint64_t default_memory_budget();

}  // namespace isoform::vdbio

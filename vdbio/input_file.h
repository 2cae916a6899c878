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

// The most memory one file's data may take once decoded. A file whose sizes
// claim more is refused before anything is allocated for it, so that a few
// bytes that lie cannot make a reader ask for more than the machine has.
// The default is half the machine's physical memory.
uint64_t default_memory_budget();

// The budget in force for every read in this process: the last one set, or
// the default.
uint64_t memory_budget();

// Sets the budget for the reads that follow; 0 restores the default.
void set_memory_budget(uint64_t bytes);

// "62.5 KiB", "2.2 MiB", "12.0 GiB": how budgets and sizes are shown in
// messages.
std::string size_text(uint64_t bytes);

}  // namespace isoform::vdbio

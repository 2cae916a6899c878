// Whole-file input for the readers: mesh files are parsed from memory, which
// keeps the parsers free of I/O and lets them see the file's size up front.
#pragma once

#include <string>

namespace isoform::meshio {

// Returns the content of the file at path. Throws IoError naming the path
// and the system's reason when it cannot be opened or read.
std::string read_file_bytes(const std::string& path);

}  // namespace isoform::meshio

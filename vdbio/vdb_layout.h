// The grid table of an OpenVDB file. OpenVDB reads a truncated file without
// complaint (a short stream leaves zeros in the leaves), so before trusting
// a file isoform reads its header and grid table itself and checks that
// every grid's data ends within the file.
#pragma once

#include <string>
#include <vector>

namespace isoform::vdbio {

// True if the file starts with OpenVDB's magic number; throws IoError if the
// file is missing or unreadable.
bool has_vdb_magic(const std::string& path);

// The names of the file's grids in file order, as io::File::readGrid takes
// them (a second grid of the same name is "name[1]"). Throws FormatError
// "PATH: not an OpenVDB file" or "PATH: truncated or damaged OpenVDB file
// (...)", Unsupported for file versions or grid types OpenVDB cannot read,
// IoError if the file is missing or unreadable.
std::vector<std::string> read_vdb_grid_table(const std::string& path);

}  // namespace isoform::vdbio

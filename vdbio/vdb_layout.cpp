// The grid table of an OpenVDB file, as isoform's own walk of the file
// (vdb_check.h) finds it.
#include "vdb_layout.h"

#include <cstdint>
#include <cstring>

#include "input_file.h"
#include "vdb_check.h"

namespace isoform::vdbio {

bool has_vdb_magic(const std::string& path) {
  const std::string prefix = read_prefix(path, sizeof(std::int64_t));
  if (prefix.size() < sizeof(std::int64_t)) return false;
  std::int64_t magic = 0;
  std::memcpy(&magic, prefix.data(), sizeof magic);
  return magic == 0x56444220;  // OpenVDB's magic number, "VDB "
}

std::vector<std::string> read_vdb_grid_table(const std::string& path) {
  std::vector<std::string> names;
  for (const VdbGridEntry& g : check_vdb_layout(path).grids) names.push_back(g.unique_name);
  return names;
}

}  // namespace isoform::vdbio

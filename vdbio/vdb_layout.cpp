// The grid table of an OpenVDB file, read with OpenVDB's own header and grid
// descriptor readers so that every format version is understood as OpenVDB
// understands it.
#include "vdb_layout.h"

#include <openvdb/io/Archive.h>
#include <openvdb/io/GridDescriptor.h>
#include <openvdb/openvdb.h>

#include <algorithm>
#include <cstring>
#include <fstream>

#include "input_file.h"
#include "libcore/errors.h"
#include "vdb_convert.h"
#include "vdb_errors.h"

namespace isoform::vdbio {

namespace {

// io::File reads only files with a grid table (version 222 and later); older
// ones it refuses, and so does isoform.
constexpr std::uint32_t kOldestReadable = openvdb::OPENVDB_FILE_VERSION_NODE_MASK_COMPRESSION;

struct Table {
  std::vector<std::string> names;
  std::int64_t data_end = 0;  // the largest end offset of any grid
};

// Archive keeps its header and grid-count readers for subclasses (io::File
// and io::Stream are two); this one reads the grid table and nothing else.
// The stream fails if the table itself is cut short.
class TableReader : public openvdb::io::Archive {
 public:
  Table read(std::istream& in, const std::string& path) {
    readHeader(in);
    if (fileVersion() < kOldestReadable || !inputHasGridOffsets())
      throw Unsupported(path + ": OpenVDB file version " + std::to_string(fileVersion()) +
                        " is older than " + std::to_string(kOldestReadable) +
                        ", the oldest OpenVDB reads");
    setFormatVersion(in);
    setLibraryVersion(in);
    setDataCompression(in);
    openvdb::MetaMap().readMeta(in);
    Table table;
    const std::int32_t count = readGridCount(in);
    for (std::int32_t i = 0; i < count && in; ++i) {
      openvdb::io::GridDescriptor descriptor;
      descriptor.read(in);
      if (!in) break;
      table.names.push_back(openvdb::io::GridDescriptor::nameAsString(descriptor.uniqueName()));
      table.data_end = std::max(table.data_end, descriptor.getEndPos());
      descriptor.seekToEnd(in);
    }
    return table;
  }
};

}  // namespace

bool has_vdb_magic(const std::string& path) {
  const std::string prefix = read_prefix(path, sizeof(std::int64_t));
  if (prefix.size() < sizeof(std::int64_t)) return false;
  std::int64_t magic = 0;
  std::memcpy(&magic, prefix.data(), sizeof magic);
  return magic == openvdb::OPENVDB_MAGIC;
}

std::vector<std::string> read_vdb_grid_table(const std::string& path) {
  initialize_openvdb();
  if (!has_vdb_magic(path)) throw FormatError(path + ": not an OpenVDB file");
  const std::uintmax_t size = input_file_size(path);
  std::ifstream in(path, std::ios::binary);
  const Table table = reading_vdb(path, [&] { return TableReader().read(in, path); });
  if (!in)
    throw FormatError(path + ": truncated or damaged OpenVDB file (its grid table is cut short)");
  if (table.data_end < 0 || std::uintmax_t(table.data_end) > size)
    throw FormatError(path + ": truncated or damaged OpenVDB file (its grids end at byte " +
                      std::to_string(table.data_end) + " but the file has " + std::to_string(size) +
                      " bytes)");
  return table.names;
}

}  // namespace isoform::vdbio

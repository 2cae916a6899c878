// The walk of one OpenVDB tree, topology and buffers (see vdb_check.h),
// and the pieces of it the metadata walk shares.
#pragma once

#include <cstdint>
#include <string>

#include "byte_cursor.h"

namespace isoform::vdbio {

struct TreeFormat {
  std::string type;          // e.g. "Tree_float_5_4_3"
  bool half = false;         // real values stored as 16-bit floats
  uint32_t compression = 0;  // io::COMPRESS_* flags of the grid
};

// Walks the tree that starts at the cursor and must end by end_pos: the
// topology, then the buffers, as OpenVDB reads them. Internal nodes' value
// chunks are decoded here (OpenVDB would leak a half-built node if one
// failed to decode); leaf chunks are checked by their headers. Throws
// Unsupported for tree types other than the 5-4-3 trees of bool, mask,
// float, double, int32, int64 and vec3i/s/d values; FormatError when the
// tree's decoded size would pass memory_budget bytes.
void check_tree(ByteCursor& in, const TreeFormat& format, uint64_t end_pos, uint64_t memory_budget);

// A blosc chunk's 16-byte header: it must say `expected` bytes decoded
// and `chunk_bytes` bytes compressed, the chunk's own length, so that
// blosc never reads or writes past either buffer.
void check_blosc_header(const ByteCursor& in, const unsigned char* header, uint64_t chunk_bytes, uint64_t expected,
                        const char* what);

// Whether OpenVDB (initialised) knows the metadata or grid type.
bool metadata_type_registered(const std::string& type);
bool grid_type_registered(const std::string& type);

}  // namespace isoform::vdbio

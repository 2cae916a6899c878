// OpenVDB's readers trust every size a file gives: a string length becomes
// an allocation, a negative chunk size a write past a buffer, a child table
// a tree built before its data are checked (and leaked when they fail). So
// isoform walks a file's structure itself, byte by byte and bounded by the
// file, before OpenVDB reads any of it, and refuses what OpenVDB could not
// read safely: lengths that are negative, larger than what remains, or
// larger than the decoded size they can have; compression headers that do
// not match their chunk; node tables that repeat or misplace a node; and
// trees whose decoded size exceeds the memory budget.
//
// The walk follows OpenVDB 10's own readers (io::Archive, GridDescriptor,
// MetaMap, the maps, RootNode, InternalNode, LeafNode, readCompressedValues)
// for file versions 222 and later, the oldest io::File reads.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace isoform::vdbio {

struct VdbGridEntry {
  std::string unique_name;  // as io::File::readGrid takes it ("name[1]" for a second "name")
  std::string type;         // without the half-float suffix, e.g. "Tree_float_5_4_3"
  std::string parent;       // the grid this one instances, or empty
  int parent_index = -1;    // its index, as OpenVDB finds it by that name
  bool half = false;        // reals stored as 16-bit floats: as the grid's metadata say, which
                            // OpenVDB follows rather than the type name's suffix
  int64_t grid_pos = 0, block_pos = 0, end_pos = 0;
};

inline bool operator==(const VdbGridEntry& a, const VdbGridEntry& b) {
  return a.unique_name == b.unique_name && a.type == b.type && a.parent == b.parent &&
         a.parent_index == b.parent_index && a.half == b.half && a.grid_pos == b.grid_pos &&
         a.block_pos == b.block_pos && a.end_pos == b.end_pos;
}

struct VdbLayout {
  uint32_t version = 0;
  uint64_t file_size = 0;
  std::vector<VdbGridEntry> grids;
};

// Checks the header, the file's metadata, the grid table, and every grid's
// metadata and transform: all that io::File::open and readGridMetadata
// read. Throws FormatError "PATH: not an OpenVDB file" or "PATH: truncated
// or damaged OpenVDB file (...)", Unsupported for versions, grid or
// metadata types it does not check, IoError if unreadable.
VdbLayout check_vdb_layout(const std::string& path);

// Checks grid i's tree (topology and buffers; for an instance, its
// parent's), the rest of what io::File::readGrid reads. Its decoded size
// must stay within memory_budget bytes. Throws as check_vdb_layout does.
void check_vdb_grid(const std::string& path, const VdbLayout& layout, int i, uint64_t memory_budget);

}  // namespace isoform::vdbio

// Small OpenVDB files of every kind OpenVDB writes and isoform's file check
// must accept: each value type of the 5-4-3 trees, tiles at every level,
// inactive values that take every mask-compression flag, half floats, every
// map, repeated names, instanced trees, and each compression. The file-check
// tests and the fuzzers' seed corpora are made from them.
#pragma once

#include <openvdb/openvdb.h>

#include <string>
#include <vector>

namespace isoform::vdbio::test {

struct VdbSample {
  std::string name;
  openvdb::GridPtrVec grids;
};

// The samples; each holds one or a few grids.
std::vector<VdbSample> vdb_samples();

// io::COMPRESS_* combinations OpenVDB writes: none, zip, zip with active
// masks, blosc, blosc with active masks.
std::vector<uint32_t> vdb_compressions();

// Writes the sample's grids to path with the given compression.
void write_vdb_sample(const VdbSample& sample, uint32_t compression, const std::string& path);

}  // namespace isoform::vdbio::test

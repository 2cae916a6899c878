// NIfTI-1 and NIfTI-2 files written field by field, for the reader's tests
// and the fuzzers' seeds: either byte order, any datatype, gzip or not, one
// file or a .hdr/.img pair, and headers that lie.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace isoform::vdbio::test {

struct NiftiSample {
  int version = 1;  // 1 (348-byte header) or 2 (540 bytes)
  bool big_endian = false;
  int64_t dim[8] = {3, 1, 1, 1, 1, 1, 1, 1};
  int datatype = 16;  // NIfTI's code: 2 u8, 4 i16, 16 f32, 64 f64, 512 u16, ...
  int bitpix = -1;    // -1: the datatype's own
  double pixdim[8] = {1, 1, 1, 1, 1, 1, 1, 1};
  int64_t vox_offset = -1;  // -1: just past the header and its 4 extension bytes
  double scl_slope = 0, scl_inter = 0;
  int qform_code = 0, sform_code = 0;
  double quatern[3] = {0, 0, 0}, qoffset[3] = {0, 0, 0};
  double srow[3][4] = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}};
  int xyzt_units = 2;  // millimetres
  std::string magic;   // "": "n+1" / "n+2" (one file)
  // The samples as numbers, x fastest, converted to the datatype; fewer
  // than the dims hold give a short file.
  std::vector<double> samples;
};

// The sample's header, its extension bytes and its samples.
std::string nifti_bytes(const NiftiSample& sample);

// Writes the bytes to path, gzip-compressed when `gzip`.
void write_file(const std::string& path, const std::string& bytes, bool gzip = false);

}  // namespace isoform::vdbio::test

// Dense scans (headerless raw files and NRRD files) read into libcore's
// DenseVolume: one grid named "density", class Fog, samples as floats.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "libcore/volume.h"

namespace isoform::vdbio {

// The first eight follow isoform_scalar_type; 64-bit integers come only
// from files that say so (NIfTI).
enum class ScalarType { U8, I8, U16, I16, U32, I32, F32, F64, I64, U64 };

// "u8", "i8", "u16", ..., "f64", as messages name sample types.
const char* scalar_type_name(ScalarType type);

// Bytes of one sample.
size_t sample_bytes(ScalarType type);

// `count` samples of the type, in the given byte order, as floats.
std::vector<float> decode_samples(const unsigned char* bytes, size_t count, ScalarType type,
                                  bool big_endian);

// How a headerless raw file holds its samples: x fastest, then y, then z.
struct RawLayout {
  Index3 dims{0, 0, 0};  // samples per axis, each at least 1; no default
  ScalarType type = ScalarType::U16;
  bool big_endian = false;         // byte order of multi-byte samples
  Vec3d spacing{1, 1, 1};          // world units between samples; non-zero
  Vec3d origin{0, 0, 0};           // world position of sample (0, 0, 0)
  std::uint64_t header_bytes = 0;  // bytes skipped at the start of the file
};

// Throws InvalidArgument for a bad layout, IoError if the file cannot be
// read, FormatError if its size is not exactly header_bytes plus the
// samples ("head.raw: 761000 bytes, but 64x64x93 u16 samples need 761856")
// or a sample is NaN or infinite.
std::shared_ptr<DenseVolume> read_raw(const std::string& path, const RawLayout& layout);

// True if the file starts with "NRRD" (the NRRD magic, any version); throws
// IoError if it is missing or unreadable.
bool has_nrrd_magic(const std::string& path);

// Reads a 3-D scalar NRRD (.nrrd, or a .nhdr header with its data file) of
// any sample type, raw or gzip encoded, with Teem. The index-to-world map
// comes from "space directions" and "space origin" when present (any
// orientation, in the file's own space), else from "spacings" (1 where
// missing) with the origin at 0. Throws FormatError with Teem's message for
// unreadable files, Unsupported for non-3-D or non-scalar arrays.
std::shared_ptr<DenseVolume> read_nrrd(const std::string& path);

}  // namespace isoform::vdbio

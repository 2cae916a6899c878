// Dense scans read into a DenseVolume: raw files by layout, NRRD with Teem.
#include "dense_read.h"

#include <teem/nrrd.h>

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <memory>
#include <mutex>
#include <vector>

#include "input_file.h"
#include "nrrd_check.h"
#include "libcore/errors.h"
#include "libcore/out_of_memory.h"

namespace isoform::vdbio {

namespace {

std::string dims_text(const Index3& dims) {
  return std::to_string(dims[0]) + "x" + std::to_string(dims[1]) + "x" + std::to_string(dims[2]);
}

}  // namespace

size_t sample_bytes(ScalarType type) {
  switch (type) {
    case ScalarType::U8:
    case ScalarType::I8:
      return 1;
    case ScalarType::U16:
    case ScalarType::I16:
      return 2;
    case ScalarType::U32:
    case ScalarType::I32:
    case ScalarType::F32:
      return 4;
    case ScalarType::F64:
    case ScalarType::I64:
    case ScalarType::U64:
      return 8;
  }
  throw InvalidArgument("unknown scalar type " + std::to_string(int(type)));
}

namespace {

void check_layout(const std::string& path, const RawLayout& layout) {
  if (layout.dims[0] < 1 || layout.dims[1] < 1 || layout.dims[2] < 1)
    throw InvalidArgument(path + ": raw dims must be at least 1 on each axis, not " +
                          dims_text(layout.dims));
  sample_bytes(layout.type);  // throws for a value outside ScalarType
  for (int a = 0; a < 3; ++a) {
    if (!std::isfinite(layout.spacing[a]) || layout.spacing[a] == 0.0)
      throw InvalidArgument(path + ": raw spacing must be finite and non-zero on each axis");
    if (!std::isfinite(layout.origin[a]))
      throw InvalidArgument(path + ": raw origin must be finite");
  }
}

// The file size the layout promises; InvalidArgument if it overflows.
std::uint64_t expected_size(const std::string& path, const RawLayout& layout) {
  std::uint64_t bytes = sample_bytes(layout.type);
  for (int a = 0; a < 3; ++a)
    if (__builtin_mul_overflow(bytes, std::uint64_t(layout.dims[a]), &bytes))
      throw InvalidArgument(path + ": raw dims " + dims_text(layout.dims) + " are too large");
  if (__builtin_add_overflow(bytes, layout.header_bytes, &bytes))
    throw InvalidArgument(path + ": raw header_bytes is too large");
  return bytes;
}

template <class T>
void decode(const unsigned char* bytes, size_t count, bool swap, float* out) {
  unsigned char sample[sizeof(T)];
  for (size_t i = 0; i < count; ++i, bytes += sizeof(T)) {
    std::memcpy(sample, bytes, sizeof(T));
    if (swap) std::reverse(sample, sample + sizeof(T));
    T v;
    std::memcpy(&v, sample, sizeof(T));
    out[i] = float(v);
  }
}

struct NrrdNuke {
  void operator()(Nrrd* nrrd) const { nrrdNuke(nrrd); }
};
using NrrdPtr = std::unique_ptr<Nrrd, NrrdNuke>;

// Teem reports errors through biff, whose messages live in process-wide
// state; every Teem call here holds this lock so messages are not mixed.
std::mutex& teem_mutex() {
  static std::mutex mutex;
  return mutex;
}

// Takes (and frees) the message biff holds for the nrrd library, one line.
std::string take_biff_message() {
  char* text = biffGetDone(NRRD);
  std::string message = text ? text : "";
  std::free(text);
  while (!message.empty() && message.back() == '\n') message.pop_back();
  std::replace(message.begin(), message.end(), '\n', ' ');
  return message;
}

void check_scalar_3d(const Nrrd& nrrd, const std::string& path) {
  if (nrrd.dim != 3)
    throw Unsupported(path + ": a " + std::to_string(nrrd.dim) +
                      "-D NRRD; isoform reads 3-D scalar volumes only");
  if (nrrd.type == nrrdTypeBlock)
    throw Unsupported(path + ": NRRD samples of type block; isoform reads numbers only");
  for (unsigned a = 0; a < 3; ++a) {
    const int kind = nrrd.axis[a].kind;
    if (kind != nrrdKindUnknown && !nrrdKindIsDomain(kind))
      throw Unsupported(path + ": NRRD axis " + std::to_string(a) + " is of kind " +
                        airEnumStr(nrrdKind, kind) + ", not a spatial axis; isoform reads " +
                        "3-D scalar volumes only");
    if (nrrd.axis[a].size > size_t(INT_MAX))
      throw Unsupported(path + ": NRRD axis " + std::to_string(a) + " is too long");
  }
}

// Column a of the linear part: the axis's space direction, or else its
// spacing (1 where missing) along index axis a.
Vec3d axis_vector(const Nrrd& nrrd, int a) {
  const NrrdAxisInfo& axis = nrrd.axis[a];
  if (nrrd.spaceDim)
    return {axis.spaceDirection[0], axis.spaceDirection[1], axis.spaceDirection[2]};
  Vec3d v{0, 0, 0};
  v[a] = std::isnan(axis.spacing) ? 1.0 : axis.spacing;
  return v;
}

// "space directions" are the columns of the linear part and "space origin"
// the position of sample (0, 0, 0); without them, per-axis "spacings".
Affine nrrd_transform(const Nrrd& nrrd, const std::string& path) {
  if (nrrd.spaceDim != 0 && nrrd.spaceDim != 3)
    throw Unsupported(path + ": a NRRD in " + std::to_string(nrrd.spaceDim) +
                      "-D space; isoform needs 3-D space");
  Affine affine;
  for (int a = 0; a < 3; ++a) {
    const Vec3d column = axis_vector(nrrd, a);
    for (int r = 0; r < 3; ++r) {
      if (!std::isfinite(column[r]))
        throw FormatError(path + ": NRRD axis " + std::to_string(a) + " has no usable " +
                          (nrrd.spaceDim ? "space direction" : "spacing"));
      affine.m[r][a] = column[r];
    }
  }
  for (int r = 0; r < 3; ++r) {
    const bool has_origin = nrrd.spaceDim && std::isfinite(nrrd.spaceOrigin[r]);
    affine.m[r][3] = has_origin ? nrrd.spaceOrigin[r] : 0.0;
  }
  if (affine.determinant() == 0.0)
    throw FormatError(path + ": NRRD axes are degenerate (zero spacing or parallel directions)");
  return affine;
}

// The patient frame and the unit a NRRD's space fields state ("" where not).
std::string nrrd_space(const Nrrd& nrrd) {
  switch (nrrd.space) {
    case nrrdSpaceRightAnteriorSuperior:
      return "RAS";
    case nrrdSpaceLeftAnteriorSuperior:
      return "LAS";
    case nrrdSpaceLeftPosteriorSuperior:
    case nrrdSpaceScannerXYZ:  // Teem's synonym of LPS
      return "LPS";
    default:
      return "";
  }
}

std::string nrrd_unit(const Nrrd& nrrd) {
  if (nrrd.spaceDim != 3 || !nrrd.spaceUnits[0]) return "";
  const std::string unit = nrrd.spaceUnits[0];
  for (int a = 1; a < 3; ++a)
    if (!nrrd.spaceUnits[a] || unit != nrrd.spaceUnits[a]) return "";
  if (unit == "mm" || unit == "m" || unit == "um") return unit;
  if (unit == "millimeter" || unit == "millimeters") return "mm";
  return "";
}

}  // namespace

const char* scalar_type_name(ScalarType type) {
  static const char* const names[] = {"u8", "i8", "u16", "i16", "u32", "i32", "f32", "f64", "i64", "u64"};
  return names[int(type)];
}

std::vector<float> decode_samples(const unsigned char* in, size_t count, ScalarType type,
                                  bool big_endian) {
  constexpr bool host_big = __BYTE_ORDER__ == __ORDER_BIG_ENDIAN__;
  const bool swap = big_endian != host_big;
  std::vector<float> out(count);
  switch (type) {
    case ScalarType::U8:
      decode<std::uint8_t>(in, count, swap, out.data());
      break;
    case ScalarType::I8:
      decode<std::int8_t>(in, count, swap, out.data());
      break;
    case ScalarType::U16:
      decode<std::uint16_t>(in, count, swap, out.data());
      break;
    case ScalarType::I16:
      decode<std::int16_t>(in, count, swap, out.data());
      break;
    case ScalarType::U32:
      decode<std::uint32_t>(in, count, swap, out.data());
      break;
    case ScalarType::I32:
      decode<std::int32_t>(in, count, swap, out.data());
      break;
    case ScalarType::F32:
      decode<float>(in, count, swap, out.data());
      break;
    case ScalarType::F64:
      decode<double>(in, count, swap, out.data());
      break;
    case ScalarType::I64:
      decode<std::int64_t>(in, count, swap, out.data());
      break;
    case ScalarType::U64:
      decode<std::uint64_t>(in, count, swap, out.data());
      break;
  }
  return out;
}


std::shared_ptr<DenseVolume> read_raw(const std::string& path, const RawLayout& layout) {
  check_layout(path, layout);
  const std::uint64_t need = expected_size(path, layout);
  const std::uintmax_t size = input_file_size(path);
  if (size != need)
    throw FormatError(
        path + ": " + std::to_string(size) + " bytes, but " + dims_text(layout.dims) + " " +
        scalar_type_name(layout.type) + " samples need " + std::to_string(need) +
        (layout.header_bytes ? " (with " + std::to_string(layout.header_bytes) + " header bytes)"
                             : std::string()));
  const size_t count = size_t(layout.dims[0]) * size_t(layout.dims[1]) * size_t(layout.dims[2]);
  // The file's samples and their float copy.
  const uint64_t in_memory = need - layout.header_bytes + uint64_t(count) * 4;
  if (in_memory > memory_budget())
    throw FormatError(path + ": raw data of " + dims_text(layout.dims) + " samples would take " +
                      size_text(in_memory) + " in memory, beyond the budget of " + size_text(memory_budget()));
  std::vector<unsigned char> bytes(size_t(need - layout.header_bytes));
  std::ifstream in(path, std::ios::binary);
  in.seekg(std::streamoff(layout.header_bytes));
  in.read(reinterpret_cast<char*>(bytes.data()), std::streamsize(bytes.size()));
  if (!in) throw IoError(path + ": read failed");
  return std::make_shared<DenseVolume>(
      "density", GridClass::Fog, decode_samples(bytes.data(), count, layout.type, layout.big_endian), layout.dims,
      Affine::scale_translate(layout.spacing, layout.origin), path);
}

namespace {

// Teem's read of a checked file, converted to float.
std::shared_ptr<DenseVolume> load_nrrd(const std::string& path) {
  Index3 dims;
  Affine affine;
  std::vector<float> values;
  std::string space, unit;
  {
    std::lock_guard<std::mutex> lock(teem_mutex());
    NrrdPtr nrrd(nrrdNew());
    if (nrrdLoad(nrrd.get(), path.c_str(), nullptr))
      throw FormatError(path + ": not a readable NRRD file (" + take_biff_message() + ")");
    check_scalar_3d(*nrrd, path);
    affine = nrrd_transform(*nrrd, path);
    space = nrrd_space(*nrrd);
    unit = nrrd_unit(*nrrd);
    for (int a = 0; a < 3; ++a) dims[a] = int(nrrd->axis[a].size);
    values.resize(size_t(dims[0]) * size_t(dims[1]) * size_t(dims[2]));
    // Teem's per-type lookup converts any sample type to float in place of
    // a converted copy of the whole array.
    float (*const lookup)(const void*, size_t) = nrrdFLookup[nrrd->type];
    for (size_t i = 0; i < values.size(); ++i) values[i] = lookup(nrrd->data, i);
  }
  auto volume = std::make_shared<DenseVolume>("density", GridClass::Fog, std::move(values), dims, affine, path);
  volume->set_frame(space, unit);
  return volume;
}

}  // namespace

bool has_nrrd_magic(const std::string& path) { return read_prefix(path, 4) == "NRRD"; }

std::shared_ptr<DenseVolume> read_nrrd(const std::string& path) {
  check_nrrd_header(path, memory_budget());
  try {
    return load_nrrd(path);
  } catch (const std::bad_alloc&) {
    throw OutOfMemory(path + ": out of memory while reading it");
  }
}

}  // namespace isoform::vdbio

// NIfTI-1 and NIfTI-2 files read by isoform's own header check and decoder
// (see nifti_read.h).
#include "nifti_read.h"

#include <algorithm>
#include <cctype>
#include <climits>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <vector>

#include "dense_read.h"
#include "gzip_inflate.h"
#include "input_file.h"
#include "libcore/errors.h"
#include "libcore/out_of_memory.h"

namespace isoform::vdbio {

namespace {

namespace fs = std::filesystem;

constexpr size_t kHeader1 = 348, kHeader2 = 540;

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return s;
}

bool ends_with(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

// What the header says, in NIfTI-2's widths whichever version the file is.
struct Header {
  int version = 1;
  bool big_endian = false;
  bool single_file = true;  // n+1 / n+2: data in the same file
  int64_t dim[8] = {};
  int datatype = 0, bitpix = 0;
  double pixdim[8] = {};
  double vox_offset = 0;
  double scl_slope = 0, scl_inter = 0;
  int qform_code = 0, sform_code = 0;
  double quatern[3] = {}, qoffset[3] = {};
  double srow[3][4] = {};
  int xyzt_units = 0;
};

// Reads header fields of either byte order from the first bytes of a file.
class Fields {
 public:
  Fields(const std::string& bytes, bool swap) : bytes_(bytes), swap_(swap) {}
  template <class T>
  T get(size_t offset) const {
    unsigned char raw[sizeof(T)];
    std::memcpy(raw, bytes_.data() + offset, sizeof(T));
    if (swap_) std::reverse(raw, raw + sizeof(T));
    T value;
    std::memcpy(&value, raw, sizeof(T));
    return value;
  }

 private:
  const std::string& bytes_;
  bool swap_;
};

int32_t swapped(int32_t v) {
  uint32_t u;
  std::memcpy(&u, &v, 4);
  u = __builtin_bswap32(u);
  std::memcpy(&v, &u, 4);
  return v;
}

// A header number as messages show it: "0", "NaN", "-2.5", "1e+30".
std::string number(double v) {
  if (std::isnan(v)) return "NaN";
  char text[32];
  std::snprintf(text, sizeof text, "%g", v);
  return text;
}

[[noreturn]] void damaged(const std::string& path, const std::string& problem) {
  throw FormatError(path + ": not a readable NIfTI file (" + problem + ")");
}

// The field offsets of NIfTI-1 (348 bytes) and NIfTI-2 (540 bytes).
Header parse_header(const std::string& path, const std::string& bytes) {
  if (bytes.size() < 4) damaged(path, "shorter than a NIfTI header");
  int32_t size;
  std::memcpy(&size, bytes.data(), 4);
  constexpr bool host_big = __BYTE_ORDER__ == __ORDER_BIG_ENDIAN__;
  Header h;
  bool swap = false;
  if (size == int32_t(kHeader1) || size == int32_t(kHeader2)) {
    swap = false;
  } else if (swapped(size) == int32_t(kHeader1) || swapped(size) == int32_t(kHeader2)) {
    swap = true;
    size = swapped(size);
  } else {
    damaged(path, "its first field, the header size, is neither 348 nor 540");
  }
  h.big_endian = host_big != swap;
  h.version = size == int32_t(kHeader1) ? 1 : 2;
  if (bytes.size() < size_t(size)) damaged(path, "its header ends early");
  const Fields f(bytes, swap);
  if (h.version == 1) {
    const std::string magic = bytes.substr(344, 4);
    if (magic != std::string("n+1\0", 4) && magic != std::string("ni1\0", 4))
      damaged(path, "no NIfTI-1 magic; an Analyze 7.5 header, whose orientation is unknown, is not read");
    h.single_file = magic[1] == '+';
    for (int i = 0; i < 8; ++i) h.dim[i] = f.get<int16_t>(40 + 2 * size_t(i));
    h.datatype = f.get<int16_t>(70);
    h.bitpix = f.get<int16_t>(72);
    for (int i = 0; i < 8; ++i) h.pixdim[i] = f.get<float>(76 + 4 * size_t(i));
    h.vox_offset = f.get<float>(108);
    h.scl_slope = f.get<float>(112);
    h.scl_inter = f.get<float>(116);
    h.xyzt_units = static_cast<unsigned char>(bytes[123]);
    h.qform_code = f.get<int16_t>(252);
    h.sform_code = f.get<int16_t>(254);
    for (int i = 0; i < 3; ++i) h.quatern[i] = f.get<float>(256 + 4 * size_t(i));
    for (int i = 0; i < 3; ++i) h.qoffset[i] = f.get<float>(268 + 4 * size_t(i));
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 4; ++c) h.srow[r][c] = f.get<float>(280 + 16 * size_t(r) + 4 * size_t(c));
  } else {
    const std::string magic = bytes.substr(4, 8);
    if (magic != std::string("n+2\0\r\n\032\n", 8) && magic != std::string("ni2\0\r\n\032\n", 8))
      damaged(path, "no NIfTI-2 magic, or one whose line-ending bytes were changed in transfer");
    h.single_file = magic[1] == '+';
    h.datatype = f.get<int16_t>(12);
    h.bitpix = f.get<int16_t>(14);
    for (int i = 0; i < 8; ++i) h.dim[i] = f.get<int64_t>(16 + 8 * size_t(i));
    for (int i = 0; i < 8; ++i) h.pixdim[i] = f.get<double>(104 + 8 * size_t(i));
    h.vox_offset = double(f.get<int64_t>(168));
    h.scl_slope = f.get<double>(176);
    h.scl_inter = f.get<double>(184);
    h.qform_code = f.get<int32_t>(344);
    h.sform_code = f.get<int32_t>(348);
    for (int i = 0; i < 3; ++i) h.quatern[i] = f.get<double>(352 + 8 * size_t(i));
    for (int i = 0; i < 3; ++i) h.qoffset[i] = f.get<double>(376 + 8 * size_t(i));
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 4; ++c) h.srow[r][c] = f.get<double>(400 + 32 * size_t(r) + 8 * size_t(c));
    h.xyzt_units = f.get<int32_t>(500);
  }
  return h;
}

// NIfTI's datatype codes for real scalars; others are named when refused.
ScalarType sample_type(const std::string& path, const Header& h) {
  struct Code {
    int code;
    ScalarType type;
  };
  static const Code kReal[] = {{2, ScalarType::U8},    {4, ScalarType::I16},  {8, ScalarType::I32},
                               {16, ScalarType::F32},  {64, ScalarType::F64}, {256, ScalarType::I8},
                               {512, ScalarType::U16}, {768, ScalarType::U32}, {1024, ScalarType::I64},
                               {1280, ScalarType::U64}};
  for (const Code& c : kReal) {
    if (c.code != h.datatype) continue;
    if (h.bitpix != int(8 * sample_bytes(c.type)))
      damaged(path, "datatype " + std::to_string(h.datatype) + " has " + std::to_string(8 * sample_bytes(c.type)) +
                        " bits per sample, but bitpix says " + std::to_string(h.bitpix));
    return c.type;
  }
  struct Named {
    int code;
    const char* name;
  };
  static const Named kOther[] = {{1, "binary"},       {32, "complex64"},  {128, "RGB24"},   {1536, "float128"},
                                 {1792, "complex128"}, {2048, "complex256"}, {2304, "RGBA32"}};
  for (const Named& n : kOther)
    if (n.code == h.datatype)
      throw Unsupported(path + ": NIfTI samples of datatype " + n.name + " (" + std::to_string(n.code) +
                        "); isoform reads real scalar samples");
  damaged(path, "unknown datatype " + std::to_string(h.datatype));
}

// The array's extent: dims 1 to 3, and the number of 3-D volumes.
struct Extent {
  Index3 dims{1, 1, 1};
  int64_t volumes = 1;
};

Extent extent_of(const std::string& path, const Header& h) {
  const int64_t n = h.dim[0];
  if (n < 1 || n > 7) damaged(path, "dim[0], the number of dimensions, is " + std::to_string(n) + ", not 1 to 7");
  Extent e;
  for (int a = 1; a <= n; ++a)
    if (h.dim[a] < 1) damaged(path, "dim[" + std::to_string(a) + "] is " + std::to_string(h.dim[a]));
  for (int a = 1; a <= std::min<int64_t>(n, 3); ++a) {
    if (h.dim[a] > INT_MAX) throw Unsupported(path + ": NIfTI dim[" + std::to_string(a) + "] is too long");
    e.dims[size_t(a - 1)] = int(h.dim[a]);
  }
  for (int a = 5; a <= n; ++a)
    if (h.dim[a] > 1)
      throw Unsupported(path + ": a " + std::to_string(n) + "-D NIfTI (dim[" + std::to_string(a) + "] is " +
                        std::to_string(h.dim[a]) + "); isoform reads 3-D volumes and the volumes of 4-D files");
  if (n >= 4) e.volumes = h.dim[4];
  return e;
}

std::string dims_text(const Extent& e) {
  std::string s = std::to_string(e.dims[0]) + "x" + std::to_string(e.dims[1]) + "x" + std::to_string(e.dims[2]);
  return e.volumes > 1 ? s + "x" + std::to_string(e.volumes) : s;
}

// pixdim[1..3], refused when zero or not finite (the sign is dropped, as
// niftilib does: qfac carries the handedness).
Vec3d voxel_sizes(const std::string& path, const Header& h) {
  Vec3d size;
  for (int a = 1; a <= 3; ++a) {
    const double d = h.pixdim[a];
    if (!std::isfinite(d) || d == 0.0)
      damaged(path, "pixdim[" + std::to_string(a) + "], a voxel size, is " + number(d));
    size[size_t(a - 1)] = std::fabs(d);
  }
  return size;
}

// The quaternion form: a rotation (b, c, d with a = sqrt(1 - b² - c² - d²)),
// the voxel sizes with qfac's sign on k, and an offset.
Affine qform_affine(const std::string& path, const Header& h, const Vec3d& size) {
  double b = h.quatern[0], c = h.quatern[1], d = h.quatern[2];
  for (int i = 0; i < 3; ++i)
    if (!std::isfinite(h.quatern[i]) || !std::isfinite(h.qoffset[i]))
      damaged(path, "its qform holds a value that is not finite");
  const double s = b * b + c * c + d * d;
  double a = 0.0;
  if (s > 1.0) {  // rounding past the unit sphere: a 180-degree turn
    const double norm = std::sqrt(s);
    b /= norm, c /= norm, d /= norm;
  } else {
    a = std::sqrt(1.0 - s);
  }
  const double R[3][3] = {{a * a + b * b - c * c - d * d, 2 * (b * c - a * d), 2 * (b * d + a * c)},
                          {2 * (b * c + a * d), a * a + c * c - b * b - d * d, 2 * (c * d - a * b)},
                          {2 * (b * d - a * c), 2 * (c * d + a * b), a * a + d * d - c * c - b * b}};
  const double qfac = h.pixdim[0] < 0 ? -1.0 : 1.0;
  const double scale[3] = {size[0], size[1], qfac * size[2]};
  Affine m;
  for (int r = 0; r < 3; ++r) {
    for (int col = 0; col < 3; ++col) m.m[r][col] = R[r][col] * scale[col];
    m.m[r][3] = h.qoffset[r];
  }
  return m;
}

Affine sform_affine(const std::string& path, const Header& h) {
  Affine m;
  for (int r = 0; r < 3; ++r)
    for (int col = 0; col < 4; ++col) {
      if (!std::isfinite(h.srow[r][col])) damaged(path, "its sform holds a value that is not finite");
      m.m[r][col] = h.srow[r][col];
    }
  if (m.determinant() == 0.0) damaged(path, "its sform is degenerate (its axes do not span space)");
  return m;
}

const char* space_unit(int xyzt_units) {
  switch (xyzt_units & 7) {
    case 1:
      return "m";
    case 2:
      return "mm";
    case 3:
      return "um";
    default:
      return "";
  }
}

// Where the samples are: this file, or the .img beside a .hdr (or .img.gz).
std::string data_file(const std::string& path, const Header& h) {
  if (h.single_file) return path;
  const std::string name = lower(path);
  std::string stem = path;
  if (ends_with(name, ".hdr.gz")) stem = path.substr(0, path.size() - 7);
  else if (ends_with(name, ".hdr")) stem = path.substr(0, path.size() - 4);
  else damaged(path, "its magic says the samples lie in a .img file beside a .hdr, but this file is no .hdr");
  for (const char* ext : {".img", ".img.gz", ".IMG", ".IMG.GZ"})
    if (fs::is_regular_file(stem + ext)) return stem + ext;
  throw IoError(path + ": its samples file " + fs::path(stem + ".img").filename().string() + " is missing");
}

bool is_gzip(const std::string& path) {
  const std::string head = read_prefix(path, 2);
  return head.size() == 2 && static_cast<unsigned char>(head[0]) == 0x1f &&
         static_cast<unsigned char>(head[1]) == 0x8b;
}

// The first bytes of the file, decoded if it is gzip: enough for either header.
std::string header_bytes(const std::string& path) {
  if (!is_gzip(path)) return read_prefix(path, kHeader2);
  std::string bytes;
  const Inflated inflated = inflate_gzip(path, 0, 0, kHeader2, [&](const unsigned char* p, size_t n) {
    bytes.append(reinterpret_cast<const char*>(p), n);
  });
  if (inflated.damaged && bytes.size() < kHeader1) damaged(path, "its gzip data do not decode");
  return bytes;
}

// `bytes` bytes of samples from byte `offset` of the (decoded) data file,
// after checking that the file can hold them.
std::vector<unsigned char> sample_bytes_of(const std::string& path, const std::string& data, uint64_t offset,
                                           uint64_t bytes, uint64_t whole_end, const std::string& what) {
  const uint64_t size = input_file_size(data);
  std::vector<unsigned char> out;
  if (!is_gzip(data)) {
    if (size < whole_end)
      damaged(path, what + " need bytes up to " + std::to_string(whole_end) + ", but " +
                        fs::path(data).filename().string() + " has " + std::to_string(size));
    out.resize(size_t(bytes));
    std::ifstream in(data, std::ios::binary);
    in.seekg(std::streamoff(offset));
    in.read(reinterpret_cast<char*>(out.data()), std::streamsize(out.size()));
    if (!in) throw IoError(data + ": read failed");
    return out;
  }
  if (whole_end / kDeflateRatio > size)
    damaged(path, what + " need " + std::to_string(whole_end) + " decoded bytes, more than " + std::to_string(size) +
                      " bytes of gzip data can hold");
  out.reserve(size_t(bytes));
  const Inflated inflated = inflate_gzip(data, 0, offset, bytes, [&](const unsigned char* p, size_t n) {
    out.insert(out.end(), p, p + n);
  });
  if (inflated.bytes < bytes)
    damaged(path, "its gzip data end " + std::string(inflated.damaged ? "in damaged data " : "") + "after " +
                      std::to_string(offset + inflated.bytes) + " of the " + std::to_string(offset + bytes) +
                      " decoded bytes " + what + " need");
  return out;
}

}  // namespace

bool has_nifti_name(const std::string& path) {
  const std::string name = lower(path);
  return ends_with(name, ".nii") || ends_with(name, ".nii.gz") || ends_with(name, ".hdr") ||
         ends_with(name, ".hdr.gz");
}

bool has_nifti_magic(const std::string& path) {
  const std::string head = read_prefix(path, kHeader1);
  if (head.size() >= 12 && head.compare(4, 8, std::string("n+2\0\r\n\032\n", 8)) == 0) return true;
  return head.size() == kHeader1 && head.compare(344, 4, std::string("n+1\0", 4)) == 0;
}

std::shared_ptr<DenseVolume> read_nifti(const std::string& path, int volume) {
  require_input_file(path);
  const Header h = parse_header(path, header_bytes(path));
  const Extent extent = extent_of(path, h);
  const ScalarType type = sample_type(path, h);
  if (volume < 0 && extent.volumes > 1)
    throw Unsupported(path + ": a 4-D NIfTI of " + std::to_string(extent.volumes) + " volumes (" + dims_text(extent) +
                      "); choose one with --volume K (the open options' volume), K from 0 to " +
                      std::to_string(extent.volumes - 1));
  if (volume >= extent.volumes)
    throw InvalidArgument(path + ": volume " + std::to_string(volume) + " asked of a NIfTI with " +
                          std::to_string(extent.volumes) + (extent.volumes == 1 ? " volume" : " volumes"));
  const Vec3d size = voxel_sizes(path, h);
  // Where the samples start.
  const double min_offset = h.single_file ? double(h.version == 1 ? kHeader1 + 4 : kHeader2 + 4) : 0.0;
  if (!std::isfinite(h.vox_offset) || h.vox_offset < min_offset || h.vox_offset > 0x1p62 ||
      h.vox_offset != std::floor(h.vox_offset))
    damaged(path, "vox_offset, where the samples start, is " + number(h.vox_offset) +
                      (h.single_file ? ", not a whole number past the header" : ""));
  // Sizes, refusing products beyond 64 bits before anything is allocated.
  const uint64_t count = uint64_t(extent.dims[0]) * uint64_t(extent.dims[1]) * uint64_t(extent.dims[2]);
  const uint64_t sample = sample_bytes(type);
  uint64_t volume_bytes = 0, all_bytes = 0, whole_end = 0;
  if (__builtin_mul_overflow(count, sample, &volume_bytes) ||
      __builtin_mul_overflow(volume_bytes, uint64_t(extent.volumes), &all_bytes) ||
      __builtin_add_overflow(all_bytes, uint64_t(h.vox_offset), &whole_end))
    damaged(path, "its dimensions " + dims_text(extent) + " are too large");
  const std::string what = dims_text(extent) + " " + scalar_type_name(type) + " samples";
  const uint64_t in_memory = volume_bytes + count * 4;
  if (volume_bytes > memory_budget() || in_memory > memory_budget())
    throw FormatError(path + ": NIfTI data of " + what + " would take " + size_text(in_memory) +
                      " in memory, beyond the budget of " + size_text(memory_budget()));
  const std::string data = data_file(path, h);
  const int index = std::max(volume, 0);
  std::vector<float> values;
  try {
    const std::vector<unsigned char> bytes =
        sample_bytes_of(path, data, uint64_t(h.vox_offset) + uint64_t(index) * volume_bytes, volume_bytes,
                        whole_end, what);
    values = decode_samples(bytes.data(), size_t(count), type, h.big_endian);
  } catch (const std::bad_alloc&) {
    throw OutOfMemory(path + ": out of memory while reading its samples");
  }
  // A slope of 0, or one that is not finite, means no scaling.
  if (std::isfinite(h.scl_slope) && h.scl_slope != 0.0) {
    const double inter = std::isfinite(h.scl_inter) ? h.scl_inter : 0.0;
    if (h.scl_slope != 1.0 || inter != 0.0)
      for (float& v : values) v = float(h.scl_slope * double(v) + inter);
  }
  const bool oriented = h.sform_code > 0 || h.qform_code > 0;
  const Affine affine = h.sform_code > 0   ? sform_affine(path, h)
                        : h.qform_code > 0 ? qform_affine(path, h, size)
                                           : Affine::scale_translate(size, {0, 0, 0});
  auto result = std::make_shared<DenseVolume>("density", GridClass::Fog, std::move(values), extent.dims, affine, path);
  result->set_frame(oriented ? "RAS" : "", space_unit(h.xyzt_units));
  return result;
}

}  // namespace isoform::vdbio

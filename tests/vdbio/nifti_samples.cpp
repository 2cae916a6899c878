// NIfTI files written field by field (see nifti_samples.h).
#include "nifti_samples.h"

#include <zlib.h>

#include <algorithm>
#include <cstring>
#include <fstream>
#include <limits>
#include <stdexcept>

namespace isoform::vdbio::test {

namespace {

class Writer {
 public:
  Writer(size_t size, bool big_endian) : bytes_(size, '\0'), swap_(big_endian != host_big()) {}
  template <class T>
  void put(size_t offset, T value) {
    put_bytes(offset, &value, sizeof value);
  }
  void put_text(size_t offset, const std::string& text) { std::memcpy(&bytes_[offset], text.data(), text.size()); }
  template <class T>
  void append(T value) {
    bytes_.resize(bytes_.size() + sizeof value);
    put_bytes(bytes_.size() - sizeof value, &value, sizeof value);
  }
  std::string& bytes() { return bytes_; }

 private:
  static bool host_big() { return __BYTE_ORDER__ == __ORDER_BIG_ENDIAN__; }
  void put_bytes(size_t offset, const void* value, size_t n) {
    unsigned char raw[8];
    std::memcpy(raw, value, n);
    if (swap_) std::reverse(raw, raw + n);
    std::memcpy(&bytes_[offset], raw, n);
  }
  std::string bytes_;
  bool swap_;
};

int datatype_bits(int datatype) {
  switch (datatype) {
    case 2:
    case 256:
      return 8;
    case 4:
    case 512:
      return 16;
    case 8:
    case 16:
    case 768:
      return 32;
    case 64:
    case 1024:
    case 1280:
      return 64;
    case 128:
      return 24;
    default:
      return 8;
  }
}

// v as an integer type, clamped to its range (NaN as 0).
template <class T>
T integer(double v) {
  if (!(v == v)) return 0;
  const double lo = double(std::numeric_limits<T>::lowest()), hi = double(std::numeric_limits<T>::max());
  return v <= lo ? std::numeric_limits<T>::lowest() : v >= hi ? std::numeric_limits<T>::max() : T(v);
}

void append_sample(Writer& w, int datatype, double v) {
  switch (datatype) {
    case 2: w.append(integer<uint8_t>(v)); break;
    case 256: w.append(integer<int8_t>(v)); break;
    case 4: w.append(integer<int16_t>(v)); break;
    case 512: w.append(integer<uint16_t>(v)); break;
    case 8: w.append(integer<int32_t>(v)); break;
    case 768: w.append(integer<uint32_t>(v)); break;
    case 16: w.append(float(v)); break;
    case 64: w.append(double(v)); break;
    case 1024: w.append(integer<int64_t>(v)); break;
    case 1280: w.append(integer<uint64_t>(v)); break;
    default: w.append(integer<uint8_t>(v)); break;
  }
}

void header1(Writer& w, const NiftiSample& s, int64_t offset) {
  w.put<int32_t>(0, 348);
  for (int i = 0; i < 8; ++i) w.put<int16_t>(40 + 2 * size_t(i), int16_t(s.dim[i]));
  w.put<int16_t>(70, int16_t(s.datatype));
  w.put<int16_t>(72, int16_t(s.bitpix >= 0 ? s.bitpix : datatype_bits(s.datatype)));
  for (int i = 0; i < 8; ++i) w.put<float>(76 + 4 * size_t(i), float(s.pixdim[i]));
  w.put<float>(108, float(offset));
  w.put<float>(112, float(s.scl_slope));
  w.put<float>(116, float(s.scl_inter));
  w.put<uint8_t>(123, uint8_t(s.xyzt_units));
  w.put<int16_t>(252, int16_t(s.qform_code));
  w.put<int16_t>(254, int16_t(s.sform_code));
  for (int i = 0; i < 3; ++i) w.put<float>(256 + 4 * size_t(i), float(s.quatern[i]));
  for (int i = 0; i < 3; ++i) w.put<float>(268 + 4 * size_t(i), float(s.qoffset[i]));
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 4; ++c) w.put<float>(280 + 16 * size_t(r) + 4 * size_t(c), float(s.srow[r][c]));
  w.put_text(344, s.magic.empty() ? std::string("n+1\0", 4) : s.magic);
}

void header2(Writer& w, const NiftiSample& s, int64_t offset) {
  w.put<int32_t>(0, 540);
  w.put_text(4, s.magic.empty() ? std::string("n+2\0\r\n\032\n", 8) : s.magic);
  w.put<int16_t>(12, int16_t(s.datatype));
  w.put<int16_t>(14, int16_t(s.bitpix >= 0 ? s.bitpix : datatype_bits(s.datatype)));
  for (int i = 0; i < 8; ++i) w.put<int64_t>(16 + 8 * size_t(i), s.dim[i]);
  for (int i = 0; i < 8; ++i) w.put<double>(104 + 8 * size_t(i), s.pixdim[i]);
  w.put<int64_t>(168, offset);
  w.put<double>(176, s.scl_slope);
  w.put<double>(184, s.scl_inter);
  w.put<int32_t>(344, s.qform_code);
  w.put<int32_t>(348, s.sform_code);
  for (int i = 0; i < 3; ++i) w.put<double>(352 + 8 * size_t(i), s.quatern[i]);
  for (int i = 0; i < 3; ++i) w.put<double>(376 + 8 * size_t(i), s.qoffset[i]);
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 4; ++c) w.put<double>(400 + 32 * size_t(r) + 8 * size_t(c), s.srow[r][c]);
  w.put<int32_t>(500, s.xyzt_units);
}

}  // namespace

std::string nifti_bytes(const NiftiSample& s) {
  const size_t header = s.version == 1 ? 348 : 540;
  const int64_t offset = s.vox_offset >= 0 ? s.vox_offset : int64_t(header + 4);
  Writer w(header + 4, s.big_endian);  // the header, then 4 zero extension bytes
  if (s.version == 1) header1(w, s, offset);
  else header2(w, s, offset);
  if (offset > int64_t(header + 4)) w.bytes().resize(size_t(offset), '\0');
  for (double v : s.samples) append_sample(w, s.datatype, v);
  return w.bytes();
}

void write_file(const std::string& path, const std::string& bytes, bool gzip) {
  if (!gzip) {
    std::ofstream(path, std::ios::binary) << bytes;
    return;
  }
  gzFile out = gzopen(path.c_str(), "wb");
  if (!out) throw std::runtime_error(path + ": cannot write");
  gzwrite(out, bytes.data(), unsigned(bytes.size()));
  gzclose(out);
}

}  // namespace isoform::vdbio::test

// Decoding PLY scalars from bytes or text.
#include "ply_values.h"

#include <cmath>
#include <cstdint>

#include "byte_order.h"

namespace isoform::meshio {
namespace {

// bits holds the value's bytes in host order, zero-extended.
double decode(PlyType type, uint64_t bits) {
  switch (type) {
    case PlyType::int8: return static_cast<int8_t>(bits);
    case PlyType::uint8: return static_cast<uint8_t>(bits);
    case PlyType::int16: return static_cast<int16_t>(bits);
    case PlyType::uint16: return static_cast<uint16_t>(bits);
    case PlyType::int32: return static_cast<int32_t>(bits);
    case PlyType::uint32: return static_cast<uint32_t>(bits);
    case PlyType::float32: return float_from_bits(static_cast<uint32_t>(bits));
    case PlyType::float64: return double_from_bits(bits);
  }
  return 0.0;
}

bool in_range(PlyType type, long long value) {
  switch (type) {
    case PlyType::int8: return value >= INT8_MIN && value <= INT8_MAX;
    case PlyType::uint8: return value >= 0 && value <= UINT8_MAX;
    case PlyType::int16: return value >= INT16_MIN && value <= INT16_MAX;
    case PlyType::uint16: return value >= 0 && value <= UINT16_MAX;
    case PlyType::int32: return value >= INT32_MIN && value <= INT32_MAX;
    case PlyType::uint32: return value >= 0 && value <= UINT32_MAX;
    case PlyType::float32:
    case PlyType::float64: return true;
  }
  return false;
}

// A float property is parsed as float, not as double and then rounded: the
// two roundings could differ in the last bit from the one the writer meant.
bool parse_as(PlyType type, std::string_view token, double& out) {
  if (type == PlyType::float32) {
    float value;
    if (!parse_number(token, value)) return false;
    out = value;
    return true;
  }
  if (type == PlyType::float64) return parse_number(token, out);
  long long value;
  if (!parse_number(token, value) || !in_range(type, value)) return false;
  out = static_cast<double>(value);
  return true;
}

}  // namespace

bool PlyBinaryValues::read(PlyType type, double& out) {
  size_t size = ply_type_size(type);
  if (bytes_.size() - pos_ < size) return false;
  const auto* p = reinterpret_cast<const unsigned char*>(bytes_.data() + pos_);
  out = decode(type, big_endian_ ? load_big_endian(p, size) : load_little_endian(p, size));
  pos_ += size;
  return true;
}

bool PlyBinaryValues::at_end() const {
  for (size_t i = pos_; i < bytes_.size(); ++i)
    if (bytes_[i] != '\n' && bytes_[i] != '\r' && bytes_[i] != ' ') return false;
  return true;
}

bool PlyAsciiValues::read(PlyType type, double& out) {
  std::string_view token = cursor_.token();
  if (token.empty()) {
    problem_ = "the file ends early (truncated?)";
    return false;
  }
  if (parse_as(type, token, out)) return true;
  double wide;
  const bool too_big = type == PlyType::float32 && parse_number(token, wide) && std::isfinite(wide);
  const std::string what = too_big ? "is beyond the range of a float" : std::string("is not a ") + ply_type_name(type);
  problem_ = "line " + std::to_string(cursor_.line()) + ": \"" + std::string(token) + "\" " + what;
  return false;
}

}  // namespace isoform::meshio

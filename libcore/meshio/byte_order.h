// Fixed byte orders for the binary formats. Values are assembled with shifts,
// so the files come out the same on any host, whatever its own byte order.
#pragma once

#include <cstdint>
#include <cstring>

namespace isoform::meshio {

// Reads an unsigned integer of `size` bytes (1, 2, 4 or 8) at p.
inline uint64_t load_little_endian(const unsigned char* p, size_t size) {
  uint64_t value = 0;
  for (size_t i = size; i-- > 0;) value = (value << 8) | p[i];
  return value;
}

inline uint64_t load_big_endian(const unsigned char* p, size_t size) {
  uint64_t value = 0;
  for (size_t i = 0; i < size; ++i) value = (value << 8) | p[i];
  return value;
}

inline void store_little_endian(unsigned char* p, uint64_t value, size_t size) {
  for (size_t i = 0; i < size; ++i) p[i] = static_cast<unsigned char>(value >> (8 * i));
}

inline uint32_t float_bits(float value) {
  uint32_t bits;
  std::memcpy(&bits, &value, sizeof bits);
  return bits;
}

inline float float_from_bits(uint32_t bits) {
  float value;
  std::memcpy(&value, &bits, sizeof value);
  return value;
}

inline double double_from_bits(uint64_t bits) {
  double value;
  std::memcpy(&value, &bits, sizeof value);
  return value;
}

inline void store_float_le(unsigned char* p, float value) {
  store_little_endian(p, float_bits(value), 4);
}

inline void store_double_le(unsigned char* p, double value) {
  uint64_t bits;
  std::memcpy(&bits, &value, sizeof bits);
  store_little_endian(p, bits, 8);
}

inline void store_int32_le(unsigned char* p, int32_t value) {
  store_little_endian(p, static_cast<uint32_t>(value), 4);
}

}  // namespace isoform::meshio

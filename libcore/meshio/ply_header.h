// The header of a PLY file (Turk's format, as in the Stanford repository):
// the encoding, and the elements with their properties in file order.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace isoform::meshio {

enum class PlyType { int8, uint8, int16, uint16, int32, uint32, float32, float64 };

// Bytes of one value of type in the binary encodings.
size_t ply_type_size(PlyType type);
// The type's name as PLY writes it ("uchar", "float"), for messages.
const char* ply_type_name(PlyType type);

struct PlyProperty {
  std::string name;
  PlyType type = PlyType::float32;  // of the value, or of each list item
  bool is_list = false;
  PlyType count_type = PlyType::uint8;  // of a list's length
};

struct PlyElement {
  std::string name;
  uint64_t count = 0;
  std::vector<PlyProperty> properties;

  // Index of the property called name, or -1.
  int find(std::string_view property_name) const;
};

enum class PlyFormat { ascii, binary_little_endian, binary_big_endian };

struct PlyHeader {
  PlyFormat format = PlyFormat::ascii;
  std::vector<PlyElement> elements;
  size_t data_offset = 0;  // first byte after the end_header line
};

// Parses the header at the start of bytes. Throws FormatError naming path
// and the header line when it is not PLY or not well formed.
PlyHeader parse_ply_header(std::string_view bytes, const std::string& path);

}  // namespace isoform::meshio

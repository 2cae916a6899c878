// Reading PLY into a Mesh. The body is walked element by element in header
// order with one decoder for all encodings; elements other than vertex and
// face, and properties the Mesh has no place for, are read and dropped so
// that the position in the data stays right.
#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

#include "../errors.h"
#include "formats.h"
#include "ply_header.h"
#include "ply_values.h"

namespace isoform::meshio {
namespace {

// Slots of a vertex property in the Mesh: 0..2 the point, 3..5 the normal.
constexpr const char* kVertexSlots[] = {"x", "y", "z", "nx", "ny", "nz"};
constexpr int kNoSlot = -1;

bool to_float(double value, float& out) {
  if (!std::isfinite(value) || std::fabs(value) > std::numeric_limits<float>::max()) return false;
  out = static_cast<float>(value);
  return true;
}

std::string number_text(double value) {
  char text[32];
  return std::string(text, std::to_chars(text, text + sizeof text, value).ptr);
}

const PlyElement* find_element(const PlyHeader& header, const char* name) {
  for (const PlyElement& element : header.elements) {
    if (element.name == name) return &element;
  }
  return nullptr;
}

template <class Values>
class PlyDecoder {
 public:
  PlyDecoder(const PlyHeader& header, Values values, size_t file_size, const std::string& path)
      : header_(header), values_(std::move(values)), file_size_(file_size), path_(path) {}
  Mesh run();

 private:
  std::vector<int> vertex_slots(const PlyElement& element) const;
  void read_vertices(const PlyElement& element);
  void read_faces(const PlyElement& element);
  int face_list(const PlyElement& element) const;
  void read_corners(const PlyProperty& property);
  int32_t read_part(const PlyProperty& property);
  void append_fan(int32_t part, bool has_part);
  size_t reservation(const PlyElement& element, size_t values_per_item) const;
  void skip_element(const PlyElement& element);
  double read_property(const PlyProperty& property);
  uint64_t list_length(const PlyProperty& property);
  double value(PlyType type);
  void start(const PlyElement& element, uint64_t index);
  [[noreturn]] void fail(const std::string& what) const;

  const PlyHeader& header_;
  Values values_;
  size_t file_size_;
  const std::string& path_;
  Mesh mesh_;
  uint64_t vertex_count_ = 0;
  const PlyElement* element_ = nullptr;  // where the decoder is, for messages
  uint64_t index_ = 0;
  std::vector<int32_t> corners_;  // of the face being read
};

template <class Values>
Mesh PlyDecoder<Values>::run() {
  const PlyElement* vertices = find_element(header_, "vertex");
  if (!vertices) throw FormatError(path_ + ": the header declares no vertex element");
  if (vertices->count > uint64_t(std::numeric_limits<int32_t>::max())) {
    throw Unsupported(path_ + ": " + std::to_string(vertices->count) +
                      " vertices are more than 32-bit indices can address");
  }
  vertex_count_ = vertices->count;
  const PlyElement* faces = find_element(header_, "face");
  for (const PlyElement& element : header_.elements) {
    if (&element == vertices) {
      read_vertices(element);
    } else if (&element == faces) {
      read_faces(element);
    } else {
      skip_element(element);
    }
  }
  if (!mesh_.parts.empty()) {
    mesh_.part_count = *std::max_element(mesh_.parts.begin(), mesh_.parts.end()) + 1;
  }
  return std::move(mesh_);
}

// Normals are taken only when all three components are there.
template <class Values>
std::vector<int> PlyDecoder<Values>::vertex_slots(const PlyElement& element) const {
  std::vector<int> slots(element.properties.size(), kNoSlot);
  bool normals = true;
  for (int slot = 0; slot < 6; ++slot) {
    int found = element.find(kVertexSlots[slot]);
    if (found >= 0 && !element.properties[size_t(found)].is_list) {
      slots[size_t(found)] = slot;
    } else if (slot < 3) {
      throw FormatError(path_ + ": the vertex element has no scalar property " +
                        kVertexSlots[slot]);
    } else {
      normals = false;
    }
  }
  if (!normals) std::replace_if(slots.begin(), slots.end(), [](int s) { return s >= 3; }, kNoSlot);
  return slots;
}

template <class Values>
void PlyDecoder<Values>::read_vertices(const PlyElement& element) {
  std::vector<int> slots = vertex_slots(element);
  bool normals = std::count_if(slots.begin(), slots.end(), [](int s) { return s >= 3; }) == 3;
  size_t reserve = reservation(element, element.properties.size());
  mesh_.points.reserve(3 * reserve);
  if (normals) mesh_.normals.reserve(3 * reserve);
  for (uint64_t i = 0; i < element.count; ++i) {
    start(element, i);
    float slot_values[6] = {};
    for (size_t k = 0; k < slots.size(); ++k) {
      double read = read_property(element.properties[k]);
      if (slots[k] == kNoSlot) continue;
      if (!to_float(read, slot_values[slots[k]])) {
        fail("has " + element.properties[k].name + " = " + number_text(read) +
             ", which is not a finite float");
      }
    }
    mesh_.points.insert(mesh_.points.end(), slot_values, slot_values + 3);
    if (normals) mesh_.normals.insert(mesh_.normals.end(), slot_values + 3, slot_values + 6);
  }
}

template <class Values>
void PlyDecoder<Values>::read_faces(const PlyElement& element) {
  int list = face_list(element);
  int part = element.find("part");
  if (part >= 0 && element.properties[size_t(part)].is_list) part = -1;
  // Each face has at least a length and three corners.
  mesh_.triangles.reserve(3 * reservation(element, element.properties.size() + 3));
  for (uint64_t i = 0; i < element.count; ++i) {
    start(element, i);
    int32_t part_value = 0;
    for (size_t k = 0; k < element.properties.size(); ++k) {
      const PlyProperty& property = element.properties[k];
      if (int(k) == list) {
        read_corners(property);
      } else if (int(k) == part) {
        part_value = read_part(property);
      } else {
        read_property(property);
      }
    }
    append_fan(part_value, part >= 0);
  }
}

// The corner list: "vertex_indices" in most writers, "vertex_index" in some.
template <class Values>
int PlyDecoder<Values>::face_list(const PlyElement& element) const {
  int list = element.find("vertex_indices");
  if (list < 0) list = element.find("vertex_index");
  if (list < 0 || !element.properties[size_t(list)].is_list) {
    throw FormatError(path_ + ": the face element has no vertex_indices list");
  }
  return list;
}

template <class Values>
void PlyDecoder<Values>::read_corners(const PlyProperty& property) {
  uint64_t length = list_length(property);
  if (length < 3) fail("has " + std::to_string(length) + " corners; a face needs at least 3");
  corners_.clear();
  for (uint64_t c = 0; c < length; ++c) {
    double vertex = value(property.type);
    if (!(vertex >= 0 && vertex < double(vertex_count_) && vertex == std::floor(vertex))) {
      fail("refers to vertex " + number_text(vertex) + " but there are " +
           std::to_string(vertex_count_) + " vertices");
    }
    corners_.push_back(static_cast<int32_t>(vertex));
  }
}

// Parts index a table of parts, so they are whole numbers from 0.
template <class Values>
int32_t PlyDecoder<Values>::read_part(const PlyProperty& property) {
  double part = value(property.type);
  if (!(part >= 0 && part <= std::numeric_limits<int32_t>::max() && part == std::floor(part))) {
    fail("has part " + number_text(part) + "; parts are whole numbers from 0");
  }
  return static_cast<int32_t>(part);
}

// A convex polygon's fan from its first corner; each triangle keeps the
// polygon's part.
template <class Values>
void PlyDecoder<Values>::append_fan(int32_t part, bool has_part) {
  for (size_t k = 1; k + 1 < corners_.size(); ++k) {
    mesh_.triangles.insert(mesh_.triangles.end(), {corners_[0], corners_[k], corners_[k + 1]});
    if (has_part) mesh_.parts.push_back(part);
  }
}

// How many items of element to reserve room for: the header's count, but no
// more than the file could hold when each value takes at least one byte, so
// that a lying header cannot make the reader allocate more than the file.
template <class Values>
size_t PlyDecoder<Values>::reservation(const PlyElement& element, size_t values_per_item) const {
  return size_t(std::min<uint64_t>(element.count, file_size_ / values_per_item));
}

// An element without properties takes no bytes, however many it counts;
// returning at once keeps a huge count from costing time.
template <class Values>
void PlyDecoder<Values>::skip_element(const PlyElement& element) {
  if (element.properties.empty()) return;
  for (uint64_t i = 0; i < element.count; ++i) {
    start(element, i);
    for (const PlyProperty& property : element.properties) read_property(property);
  }
}

// Reads one property: returns a scalar's value; a list is read past (0).
template <class Values>
double PlyDecoder<Values>::read_property(const PlyProperty& property) {
  if (!property.is_list) return value(property.type);
  for (uint64_t length = list_length(property); length > 0; --length) value(property.type);
  return 0.0;
}

template <class Values>
uint64_t PlyDecoder<Values>::list_length(const PlyProperty& property) {
  double length = value(property.count_type);
  if (length < 0) fail("has a list of length " + number_text(length));
  return static_cast<uint64_t>(length);
}

template <class Values>
double PlyDecoder<Values>::value(PlyType type) {
  double read;
  if (!values_.read(type, read)) {
    throw FormatError(path_ + ": " + element_->name + " " + std::to_string(index_) + ": " +
                      values_.problem());
  }
  return read;
}

template <class Values>
void PlyDecoder<Values>::start(const PlyElement& element, uint64_t index) {
  element_ = &element;
  index_ = index;
}

template <class Values>
void PlyDecoder<Values>::fail(const std::string& what) const {
  throw FormatError(path_ + ": " + element_->name + " " + std::to_string(index_) + " " + what);
}

}  // namespace

Mesh read_ply(std::string_view bytes, const std::string& path) {
  PlyHeader header = parse_ply_header(bytes, path);
  if (header.format == PlyFormat::ascii) {
    PlyAsciiValues values(bytes, header.data_offset);
    return PlyDecoder<PlyAsciiValues>(header, std::move(values), bytes.size(), path).run();
  }
  bool big_endian = header.format == PlyFormat::binary_big_endian;
  PlyBinaryValues values(bytes, header.data_offset, big_endian);
  return PlyDecoder<PlyBinaryValues>(header, values, bytes.size(), path).run();
}

}  // namespace isoform::meshio

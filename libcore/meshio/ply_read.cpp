// Reading PLY into a Mesh. The body is walked element by element in header
// order with one decoder for all encodings; elements other than vertex and
// face, and properties the Mesh has no place for, are read and dropped so
// that the position in the data stays right.
#include <algorithm>
#include <array>
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
#include "polygon_split.h"

namespace isoform::meshio {
namespace {

// Slots of a vertex property in the Mesh, in groups as save_mesh writes
// them: the point, the normal, the curvature (Chapter 4), the colour. A group
// other than the point is taken only when all its properties are there
// (alpha may be missing: opaque).
constexpr const char* kVertexSlots[] = {"x",   "y",   "z",   "nx",  "ny",   "nz",   "k1",
                                        "k2",  "mean", "gauss", "absolute", "d1x", "d1y", "d1z",
                                        "d2x", "d2y", "d2z", "curvature_flags", "red", "green", "blue",
                                        "alpha"};
constexpr int kNormal = 3, kCurvature = 6, kFlags = 17, kColour = 18, kAlpha = 21, kSlotCount = 22;
constexpr int kNoSlot = -1;

// The group a slot belongs to, by its first slot.
int group_of(int slot) { return slot < kNormal ? 0 : slot < kCurvature ? kNormal : slot < kColour ? kCurvature : kColour; }

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
  void store_vertex(const std::vector<int>& slots, const double* value, bool precise);
  void read_edges(const PlyElement& element);
  void read_faces(const PlyElement& element);
  int face_list(const PlyElement& element) const;
  void read_corners(const PlyProperty& property);
  int32_t read_part(const PlyProperty& property);
  void append_polygon(int32_t part, bool has_part);
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
    } else if (element.name == "edge" && element.find("vertex1") >= 0 && element.find("vertex2") >= 0) {
      read_edges(element);
    } else {
      skip_element(element);
    }
  }
  // NOTE: data beyond what the header declares would be dropped without a
  // word (a header that counts too few faces loses them): refused instead.
  if (!values_.at_end()) {
    throw FormatError(path_ + ": holds more data after its last element (" + header_.elements.back().name +
                      ") than its header declares");
  }
  if (!mesh_.parts.empty()) {
    mesh_.part_count = *std::max_element(mesh_.parts.begin(), mesh_.parts.end()) + 1;
  }
  return std::move(mesh_);
}

// The slot of each vertex property, or kNoSlot; the point's three are
// required, the other groups taken whole or not at all.
template <class Values>
std::vector<int> PlyDecoder<Values>::vertex_slots(const PlyElement& element) const {
  std::vector<int> slots(element.properties.size(), kNoSlot);
  bool complete[kSlotCount] = {};  // per group, by its first slot
  for (int g : {kNormal, kCurvature, kColour}) complete[g] = true;
  std::vector<int> found(kSlotCount, -1);
  for (int slot = 0; slot < kSlotCount; ++slot) {
    const int k = element.find(kVertexSlots[slot]);
    if (k >= 0 && !element.properties[size_t(k)].is_list) {
      found[size_t(slot)] = k;
    } else if (slot < kNormal) {
      throw FormatError(path_ + ": the vertex element has no scalar property " + kVertexSlots[slot]);
    } else if (slot != kAlpha) {
      complete[group_of(slot)] = false;
    }
  }
  for (int slot = 0; slot < kSlotCount; ++slot)
    if (found[size_t(slot)] >= 0 && (slot < kNormal || complete[group_of(slot)])) slots[size_t(found[size_t(slot)])] = slot;
  return slots;
}

template <class Values>
void PlyDecoder<Values>::read_vertices(const PlyElement& element) {
  const std::vector<int> slots = vertex_slots(element);
  bool has[kSlotCount] = {};
  for (int s : slots)
    if (s != kNoSlot) has[s] = true;
  // Double-precision points are kept as well as their floats (the
  // reduction and the curvature fits read them).
  bool precise = true;
  for (size_t k = 0; k < slots.size(); ++k)
    if (slots[k] >= 0 && slots[k] < kNormal) precise &= element.properties[k].type == PlyType::float64;
  const size_t reserve = reservation(element, element.properties.size());
  mesh_.points.reserve(3 * reserve);
  if (precise) mesh_.precise_points.reserve(3 * reserve);
  if (has[kNormal]) mesh_.normals.reserve(3 * reserve);
  if (has[kColour]) mesh_.colors.reserve(4 * reserve);
  double value[kSlotCount];
  for (uint64_t i = 0; i < element.count; ++i) {
    start(element, i);
    std::fill(value, value + kSlotCount, 255.0);  // (an absent alpha: opaque)
    for (size_t k = 0; k < slots.size(); ++k) {
      const double read = read_property(element.properties[k]);
      if (slots[k] == kNoSlot) continue;
      const PlyType type = element.properties[k].type;
      // Colours of a floating-point type run from 0 to 1.
      const bool unit_colour = slots[k] >= kColour && (type == PlyType::float32 || type == PlyType::float64);
      value[slots[k]] = unit_colour ? read * 255.0 : read;
    }
    store_vertex(slots, value, precise);
  }
  // (The method that made it is not in the file.)
  if (has[kCurvature]) count_curvature_flags(mesh_.curvature);
}

// One vertex's values, checked: floats finite, flags and colours whole
// numbers from 0 to 255.
template <class Values>
void PlyDecoder<Values>::store_vertex(const std::vector<int>& slots, const double* value, bool precise) {
  const bool normals = std::count(slots.begin(), slots.end(), kNormal) > 0;
  const bool curvature = std::count(slots.begin(), slots.end(), kCurvature) > 0;
  const bool colours = std::count(slots.begin(), slots.end(), kColour) > 0;
  float f[kSlotCount] = {};
  uint8_t byte[kSlotCount] = {};
  for (int s = 0; s < kSlotCount; ++s) {
    if (s >= kNormal && !(group_of(s) == kNormal ? normals : group_of(s) == kCurvature ? curvature : colours)) continue;
    if (s == kFlags || s >= kColour) {
      const double v = s >= kColour ? std::round(value[s]) : value[s];
      if (!(v >= 0 && v <= 255 && v == std::floor(v)))
        fail("has " + std::string(kVertexSlots[s]) + " = " + number_text(value[s]) + ", which is not a whole number from 0 to 255");
      byte[s] = uint8_t(v);
    } else if (!to_float(value[s], f[s])) {
      fail("has " + std::string(kVertexSlots[s]) + " = " + number_text(value[s]) + ", which is not a finite float");
    }
  }
  mesh_.points.insert(mesh_.points.end(), f, f + 3);
  if (precise) mesh_.precise_points.insert(mesh_.precise_points.end(), value, value + 3);
  if (normals) mesh_.normals.insert(mesh_.normals.end(), f + kNormal, f + kNormal + 3);
  if (curvature) {
    VertexCurvature& c = mesh_.curvature;
    c.k1.push_back(f[6]);
    c.k2.push_back(f[7]);
    c.mean.push_back(f[8]);
    c.gauss.push_back(f[9]);
    c.absolute.push_back(f[10]);
    c.d1.insert(c.d1.end(), f + 11, f + 14);
    c.d2.insert(c.d2.end(), f + 14, f + 17);
    c.flags.push_back(byte[kFlags]);
  }
  if (colours) mesh_.colors.insert(mesh_.colors.end(), byte + kColour, byte + kColour + 4);
}

// Loose line segments (vertex1, vertex2), as save_mesh writes them.
template <class Values>
void PlyDecoder<Values>::read_edges(const PlyElement& element) {
  const int first = element.find("vertex1"), second = element.find("vertex2");
  mesh_.edges.reserve(2 * reservation(element, element.properties.size()));
  for (uint64_t i = 0; i < element.count; ++i) {
    start(element, i);
    int32_t ends[2] = {0, 0};
    for (size_t k = 0; k < element.properties.size(); ++k) {
      const double v = read_property(element.properties[k]);
      if (int(k) != first && int(k) != second) continue;
      if (!(v >= 0 && v < double(vertex_count_) && v == std::floor(v)))
        fail("refers to vertex " + number_text(v) + " but there are " + std::to_string(vertex_count_) + " vertices");
      ends[int(k) == first ? 0 : 1] = int32_t(v);
    }
    mesh_.edges.insert(mesh_.edges.end(), ends, ends + 2);
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
    append_polygon(part_value, part >= 0);
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

// The polygon's triangles by split_polygon (a convex one's fan from its first
// corner); each triangle keeps the polygon's part. When the face element
// comes before the vertex element in the header, the positions are not read
// yet, and every polygon is split into the fan from its first corner.
template <class Values>
void PlyDecoder<Values>::append_polygon(int32_t part, bool has_part) {
  size_t before = mesh_.triangles.size();
  if (mesh_.points.size() == 3 * vertex_count_) {
    const bool precise = mesh_.precise_points.size() == mesh_.points.size();
    split_polygon(corners_, [this, precise](int32_t vertex) {
      const size_t i = 3 * size_t(vertex);
      if (precise) return std::array<double, 3>{mesh_.precise_points[i], mesh_.precise_points[i + 1], mesh_.precise_points[i + 2]};
      return std::array<double, 3>{mesh_.points[i], mesh_.points[i + 1], mesh_.points[i + 2]};
    }, mesh_.triangles);
  } else {
    for (size_t k = 1; k + 1 < corners_.size(); ++k) {
      mesh_.triangles.insert(mesh_.triangles.end(), {corners_[0], corners_[k], corners_[k + 1]});
    }
  }
  if (has_part) mesh_.parts.insert(mesh_.parts.end(), (mesh_.triangles.size() - before) / 3, part);
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

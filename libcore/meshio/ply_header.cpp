// PLY header lines: "format <encoding> <version>", "element <name> <count>",
// "property <type> <name>", "property list <count type> <item type> <name>",
// "comment ..." and "obj_info ...", up to "end_header".
#include "ply_header.h"

#include <charconv>

#include "../errors.h"
#include "text_cursor.h"

namespace isoform::meshio {
namespace {

struct TypeName {
  const char* name;
  PlyType type;
};

// The original names and the sized aliases that later writers use.
constexpr TypeName kTypeNames[] = {
    {"char", PlyType::int8},     {"int8", PlyType::int8},       {"uchar", PlyType::uint8},
    {"uint8", PlyType::uint8},   {"short", PlyType::int16},     {"int16", PlyType::int16},
    {"ushort", PlyType::uint16}, {"uint16", PlyType::uint16},   {"int", PlyType::int32},
    {"int32", PlyType::int32},   {"uint", PlyType::uint32},     {"uint32", PlyType::uint32},
    {"float", PlyType::float32}, {"float32", PlyType::float32}, {"double", PlyType::float64},
    {"float64", PlyType::float64}};

class HeaderParser {
 public:
  HeaderParser(std::string_view bytes, const std::string& path) : bytes_(bytes), path_(path) {}
  PlyHeader run();

 private:
  bool next_line(std::string_view& line);
  void parse_line(std::string_view line);
  void parse_format(TextCursor& words);
  void parse_element(TextCursor& words);
  void parse_property(TextCursor& words);
  PlyType type_of(std::string_view word) const;
  std::string_view word(TextCursor& words, const char* what) const;
  [[noreturn]] void fail(const std::string& what) const;

  std::string_view bytes_;
  const std::string& path_;
  size_t pos_ = 0;
  size_t line_number_ = 0;
  bool has_format_ = false;
  bool ended_ = false;
  PlyHeader header_;
};

PlyHeader HeaderParser::run() {
  std::string_view line;
  if (!next_line(line) || line != "ply") {
    throw FormatError(path_ + ": not a PLY file (it does not begin with a \"ply\" line)");
  }
  while (!ended_) {
    if (!next_line(line)) fail("the header has no end_header line (truncated file?)");
    parse_line(line);
  }
  if (!has_format_) fail("the header has no format line");
  header_.data_offset = pos_;
  return header_;
}

// Lines end in "\n" or "\r\n"; the binary data begin right after the last.
bool HeaderParser::next_line(std::string_view& line) {
  if (pos_ >= bytes_.size()) return false;
  size_t end = bytes_.find('\n', pos_);
  if (end == std::string_view::npos) return false;
  line = bytes_.substr(pos_, end - pos_);
  if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
  pos_ = end + 1;
  ++line_number_;
  return true;
}

void HeaderParser::parse_line(std::string_view line) {
  TextCursor words(line);
  std::string_view keyword = words.token();
  if (keyword.empty() || keyword == "comment" || keyword == "obj_info") return;
  if (keyword == "format") return parse_format(words);
  if (keyword == "element") return parse_element(words);
  if (keyword == "property") return parse_property(words);
  if (keyword == "end_header") {
    ended_ = true;
    return;
  }
  fail("unknown header keyword \"" + std::string(keyword) + "\"");
}

void HeaderParser::parse_format(TextCursor& words) {
  std::string_view encoding = word(words, "an encoding");
  word(words, "a version");
  if (encoding == "ascii") {
    header_.format = PlyFormat::ascii;
  } else if (encoding == "binary_little_endian") {
    header_.format = PlyFormat::binary_little_endian;
  } else if (encoding == "binary_big_endian") {
    header_.format = PlyFormat::binary_big_endian;
  } else {
    fail("unknown encoding \"" + std::string(encoding) + "\"");
  }
  has_format_ = true;
}

void HeaderParser::parse_element(TextCursor& words) {
  PlyElement element;
  element.name = word(words, "a name");
  std::string_view count = word(words, "a count");
  const char* end = count.data() + count.size();
  std::from_chars_result result = std::from_chars(count.data(), end, element.count);
  if (result.ec != std::errc() || result.ptr != end) {
    fail("element " + element.name + " has count \"" + std::string(count) +
         "\", not a whole number");
  }
  header_.elements.push_back(std::move(element));
}

void HeaderParser::parse_property(TextCursor& words) {
  if (header_.elements.empty()) fail("a property comes before any element");
  PlyProperty property;
  std::string_view type = word(words, "a type");
  if (type == "list") {
    property.is_list = true;
    property.count_type = type_of(word(words, "a count type"));
    if (property.count_type == PlyType::float32 || property.count_type == PlyType::float64) {
      fail("a list count must have an integer type");
    }
    type = word(words, "an item type");
  }
  property.type = type_of(type);
  property.name = word(words, "a name");
  header_.elements.back().properties.push_back(std::move(property));
}

PlyType HeaderParser::type_of(std::string_view word) const {
  for (const TypeName& entry : kTypeNames) {
    if (word == entry.name) return entry.type;
  }
  fail("unknown property type \"" + std::string(word) + "\"");
}

std::string_view HeaderParser::word(TextCursor& words, const char* what) const {
  std::string_view token = words.token();
  if (token.empty()) fail(std::string("the line lacks ") + what);
  return token;
}

void HeaderParser::fail(const std::string& what) const {
  throw FormatError(path_ + ": header line " + std::to_string(line_number_) + ": " + what);
}

}  // namespace

size_t ply_type_size(PlyType type) {
  switch (type) {
    case PlyType::int8:
    case PlyType::uint8: return 1;
    case PlyType::int16:
    case PlyType::uint16: return 2;
    case PlyType::int32:
    case PlyType::uint32:
    case PlyType::float32: return 4;
    case PlyType::float64: return 8;
  }
  return 0;
}

const char* ply_type_name(PlyType type) {
  for (const TypeName& entry : kTypeNames) {
    if (entry.type == type) return entry.name;
  }
  return "?";
}

int PlyElement::find(std::string_view property_name) const {
  for (size_t i = 0; i < properties.size(); ++i) {
    if (properties[i].name == property_name) return int(i);
  }
  return -1;
}

PlyHeader parse_ply_header(std::string_view bytes, const std::string& path) {
  return HeaderParser(bytes, path).run();
}

}  // namespace isoform::meshio

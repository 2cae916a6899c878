// Whitespace is the ASCII set; the formats know no other.
#include "text_cursor.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>
#include <string>

namespace isoform::meshio {
namespace {

bool is_line_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v'; }

bool is_space(char c) { return c == '\n' || is_line_space(c); }

template <class Number>
bool parse_whole(std::string_view token, Number& out) {
  if (!token.empty() && token.front() == '+') {
    token.remove_prefix(1);
    if (!token.empty() && token.front() == '-') return false;  // "+-1" is no number
  }
  const char* end = token.data() + token.size();
  std::from_chars_result result = std::from_chars(token.data(), end, out);
  return !token.empty() && result.ec == std::errc() && result.ptr == end;
}

char lower(char c) { return c >= 'A' && c <= 'Z' ? char(c - 'A' + 'a') : c; }

}  // namespace

std::string_view TextCursor::token() {
  while (pos_ < text_.size() && is_space(text_[pos_])) ++pos_;
  size_t start = pos_;
  while (pos_ < text_.size() && !is_space(text_[pos_])) ++pos_;
  return text_.substr(start, pos_ - start);
}

std::string_view TextCursor::token_on_line() {
  while (pos_ < text_.size() && is_line_space(text_[pos_])) ++pos_;
  size_t start = pos_;
  while (pos_ < text_.size() && !is_space(text_[pos_])) ++pos_;
  return text_.substr(start, pos_ - start);
}

bool TextCursor::next_line() {
  size_t end = text_.find('\n', pos_);
  pos_ = end == std::string_view::npos ? text_.size() : end + 1;
  return pos_ < text_.size();
}

size_t TextCursor::line() const {
  return 1 + size_t(std::count(text_.begin(), text_.begin() + long(pos_), '\n'));
}

// NOTE: a number too small for a float's normal range (1e-50) is read as
// the float nearest to it (0 or a subnormal) rather than refused: it is a
// number, and a coordinate that small is zero to any mesh.
bool parse_number(std::string_view token, float& out) {
  if (parse_whole(token, out)) return true;
  double wide;
  if (!parse_whole(token, wide) || !(std::fabs(wide) < double(std::numeric_limits<float>::min()))) return false;
  out = float(wide);
  return true;
}

std::string not_a_float(std::string_view token) {
  double wide;
  const std::string quoted = "\"" + std::string(token) + "\"";
  if (parse_whole(token, wide) && std::isfinite(wide)) return quoted + " is beyond the range of a float";
  return quoted + " is not a number";
}
bool parse_number(std::string_view token, double& out) { return parse_whole(token, out); }
bool parse_number(std::string_view token, long long& out) { return parse_whole(token, out); }

bool same_keyword(std::string_view token, std::string_view keyword) {
  return token.size() == keyword.size() &&
         std::equal(token.begin(), token.end(), keyword.begin(),
                    [](char a, char b) { return lower(a) == lower(b); });
}

}  // namespace isoform::meshio

// Running out of memory while reading a file or computing a step: a
// std::bad_alloc (so whoever catches that still does) whose message names
// the file or step that asked, for the C API's isoform_last_error().
#pragma once

#include <new>
#include <string>
#include <utility>

namespace isoform {

struct OutOfMemory : std::bad_alloc {
  explicit OutOfMemory(std::string message) : message_(std::move(message)) {}
  const char* what() const noexcept override { return message_.c_str(); }

 private:
  std::string message_;
};

}  // namespace isoform

// Typed errors inside libcore. The C API turns each into an isoform_status and
// a message for isoform_last_error(); nothing of this crosses the C boundary.
#pragma once

#include <stdexcept>
#include <string>

namespace isoform {

// The caller passed something unusable: a bad option, an unknown grid.
struct InvalidArgument : std::runtime_error {
  using std::runtime_error::runtime_error;
};
// A file could not be opened, read or written.
struct IoError : std::runtime_error {
  using std::runtime_error::runtime_error;
};
// A file's content is not what its format promises, or the data are bad (NaN).
struct FormatError : std::runtime_error {
  using std::runtime_error::runtime_error;
};
// Valid input that isoform does not handle (a vector grid, say).
struct Unsupported : std::runtime_error {
  using std::runtime_error::runtime_error;
};
// The caller asked a long call to stop.
struct Cancelled : std::runtime_error {
  using std::runtime_error::runtime_error;
};

}  // namespace isoform

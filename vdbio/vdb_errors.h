// OpenVDB reports problems with its own exception types; isoform's layers
// expect the typed errors of libcore/errors.h with the file's name in them.
#pragma once

#include <openvdb/Exceptions.h>

#include <string>
#include <utility>

#include "libcore/errors.h"

namespace isoform::vdbio {

// Runs body, which reads the OpenVDB file at path, and turns OpenVDB's
// exceptions into FormatError (damaged data) or Unsupported (a grid or
// metadata type this OpenVDB does not know).
template <class Body>
decltype(auto) reading_vdb(const std::string& path, Body&& body) {
  try {
    return std::forward<Body>(body)();
  } catch (const openvdb::LookupError& e) {
    throw Unsupported(path + ": " + e.what());
  } catch (const openvdb::Exception& e) {
    throw FormatError(path + ": truncated or damaged OpenVDB file (" + e.what() + ")");
  }
}

}  // namespace isoform::vdbio

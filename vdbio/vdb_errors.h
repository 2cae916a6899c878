// OpenVDB reports problems with its own exception types; isoform's layers
// expect the typed errors of libcore/errors.h with the file's name in them.
#pragma once

#include <openvdb/Exceptions.h>

#include <new>
#include <string>
#include <utility>

#include "libcore/errors.h"
#include "libcore/out_of_memory.h"

namespace isoform::vdbio {

// Runs body, which reads the OpenVDB file at path, and turns OpenVDB's
// exceptions into FormatError (damaged data) or Unsupported (a grid or
// metadata type this OpenVDB does not know), and running out of memory
// into OutOfMemory naming the file.
template <class Body>
decltype(auto) reading_vdb(const std::string& path, Body&& body) {
  try {
    return std::forward<Body>(body)();
  } catch (const openvdb::LookupError& e) {
    throw Unsupported(path + ": " + e.what());
  } catch (const openvdb::Exception& e) {
    throw FormatError(path + ": truncated or damaged OpenVDB file (" + e.what() + ")");
  } catch (const std::bad_alloc&) {
    throw OutOfMemory(path + ": out of memory while reading it");
  }
}

}  // namespace isoform::vdbio

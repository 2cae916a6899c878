// Version, status names and the thread-local last error.
#include <string>

#include "handles.h"

namespace {
thread_local std::string last_error;
}

namespace isoform::capi {

isoform_status fail(isoform_status status, const std::string& msg) {
  last_error = msg;
  return status;
}

void clear_error() { last_error.clear(); }

}  // namespace isoform::capi

extern "C" {

int isoform_version(void) { return ISOFORM_VERSION; }

const char* isoform_last_error(void) { return last_error.c_str(); }

const char* isoform_status_name(isoform_status status) {
  switch (status) {
    case ISOFORM_OK: return "ok";
    case ISOFORM_ERR_INVALID_ARGUMENT: return "invalid argument";
    case ISOFORM_ERR_IO: return "io error";
    case ISOFORM_ERR_FORMAT: return "format error";
    case ISOFORM_ERR_UNSUPPORTED: return "unsupported";
    case ISOFORM_ERR_OUT_OF_MEMORY: return "out of memory";
    case ISOFORM_ERR_CANCELLED: return "cancelled";
    case ISOFORM_ERR_INTERNAL: return "internal error";
  }
  return "unknown status";
}

}  // extern "C"

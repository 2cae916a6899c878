// Implementation of isoform::capi::guarded; included by handles.h only.
#pragma once

#include <new>

#include "../errors.h"
#include "../out_of_memory.h"

namespace isoform::capi {

template <class Body>
isoform_status guarded(Body&& body) noexcept {
  try {
    clear_error();
    return body();
  } catch (const InvalidArgument& e) {
    return fail(ISOFORM_ERR_INVALID_ARGUMENT, e.what());
  } catch (const IoError& e) {
    return fail(ISOFORM_ERR_IO, e.what());
  } catch (const FormatError& e) {
    return fail(ISOFORM_ERR_FORMAT, e.what());
  } catch (const Unsupported& e) {
    return fail(ISOFORM_ERR_UNSUPPORTED, e.what());
  } catch (const Cancelled& e) {
    return fail(ISOFORM_ERR_CANCELLED, e.what());
  } catch (const OutOfMemory& e) {
    return fail(ISOFORM_ERR_OUT_OF_MEMORY, e.what());
  } catch (const std::bad_alloc&) {
    return fail(ISOFORM_ERR_OUT_OF_MEMORY, "out of memory");
  } catch (const std::exception& e) {
    return fail(ISOFORM_ERR_INTERNAL, std::string("internal error: ") + e.what());
  } catch (...) {
    return fail(ISOFORM_ERR_INTERNAL, "internal error: unknown exception");
  }
}

}  // namespace isoform::capi

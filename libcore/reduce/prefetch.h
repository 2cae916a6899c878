// A hint to the processor to fetch the cache line holding an address, for
// the reduction's reads in weight order all over memory (speculate.cpp). Only
// timing depends on it; without GCC or Clang it does nothing.
#pragma once

namespace isoform::reduce {

inline void prefetch(const void* address) {
#if defined(__GNUC__) || defined(__clang__)
  __builtin_prefetch(address);
#else
  (void)address;
#endif
}

}  // namespace isoform::reduce

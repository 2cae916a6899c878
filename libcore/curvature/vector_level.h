// Which vector instructions the running processor has, for the curvature
// paths built more than once (plain, AVX, AVX-512) and chosen at run time.
// The builds do the same IEEE operations in the same order (no fused
// multiply-add in any: their sources are built with -ffp-contract=off), so
// the choice changes the speed, never a bit.
#pragma once

#if defined(__x86_64__) && defined(__GNUC__) && !defined(__AVX__)
#define ISOFORM_AVX_CLONE 1
#define ISOFORM_AVX_TARGET __attribute__((target("avx")))
#define ISOFORM_AVX512_TARGET __attribute__((target("avx512f,avx512vl")))

namespace isoform {

// 2: AVX-512 (F and VL), 1: AVX, 0: neither.
inline int vector_level() {
  static const int level = __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512vl") ? 2
                           : __builtin_cpu_supports("avx")                                         ? 1
                                                                                                   : 0;
  return level;
}

}  // namespace isoform
#endif

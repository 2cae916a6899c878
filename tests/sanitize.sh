#!/usr/bin/env bash
# Builds the whole project with AddressSanitizer and UndefinedBehaviorSanitizer
# in build-asan/ and runs the test suite there. Any report fails the test
# that made it: ASan aborts on a memory error, UBSan is made to halt on its
# first finding, LeakSanitizer reports at the exit of every program the
# tests run.
#
# usage: tests/sanitize.sh [ctest arguments, e.g. -R Vdb]
#
# clang, as the fuzzers: it builds the sanitised project in a fraction of
# gcc's time, and its shared ASan runtime serves the executables, the shared
# library and the Python interpreter alike. -O1 with line tables: reports
# still name the function and line.
#
# Python tests load libisoform.so into /usr/bin/python3, which was not built
# with ASan: the runtime is preloaded for them, and Python's own
# allocations that live until exit are not reported (lsan.supp). The
# headless Blender tests are left out: Blender cannot run with a preloaded
# ASan runtime. CI does not run this script (the sanitised build and suite
# take many times as long as the normal ones); run it after changing a
# reader or the C API.
set -euo pipefail
cd "$(dirname "$0")/.."
if ! command -v clang++ >/dev/null; then apt-get install -y clang; fi
# UBSan leaves alone what fuzz/sanitizer-ignore.txt names (the system's
# headers, and the curvature fits' lanes under clang), ASan checks it all.
flags="-fsanitize=address,undefined -fno-sanitize-recover=undefined -shared-libasan -fno-omit-frame-pointer"
flags="$flags -fsanitize-ignorelist=$PWD/fuzz/sanitizer-ignore.txt"
runtime=$(clang -print-file-name=libclang_rt.asan-x86_64.so)
# The programs find the shared runtime by their run path (the build itself
# runs the test programs to list their tests).
link="$flags -Wl,-rpath,$(dirname "$runtime")"
CC=clang CXX=clang++ cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DISOFORM_BLENDER_TESTS=OFF \
  -DCMAKE_C_FLAGS_RELWITHDEBINFO="-O1 -gline-tables-only -DNDEBUG" \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -gline-tables-only -DNDEBUG" \
  -DCMAKE_C_FLAGS="$flags" -DCMAKE_CXX_FLAGS="$flags" \
  -DCMAKE_EXE_LINKER_FLAGS="$link" -DCMAKE_SHARED_LINKER_FLAGS="$link" >/dev/null
cmake --build build-asan -j"$(nproc)"

export ASAN_OPTIONS=detect_leaks=1:verify_asan_link_order=0:abort_on_error=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
export LSAN_OPTIONS=suppressions=$PWD/tests/lsan.supp
# The interpreter, not built with ASan, gets the runtime preloaded.
export LD_PRELOAD=$runtime
ctest --test-dir build-asan --output-on-failure -j"$(nproc)" "$@"

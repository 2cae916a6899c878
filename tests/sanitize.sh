#!/usr/bin/env bash
# Builds the whole project with AddressSanitizer and UndefinedBehaviorSanitizer
# (gcc, as the normal build) in build-asan/ and runs the test suite there.
# Any report fails the test that made it: ASan aborts on a memory error,
# UBSan is made to halt on its first finding, LeakSanitizer reports at the
# exit of every program the tests run.
#
# usage: tests/sanitize.sh [ctest arguments, e.g. -R Vdb]
#
# Python tests load libisoform.so into /usr/bin/python3, which was not built
# with ASan: the ASan runtime is preloaded for them, and Python's own
# allocations that live until exit are not reported (lsan.supp). The
# headless Blender tests are left out: Blender cannot run with a preloaded
# ASan runtime. CI does not run this script (the sanitised build and suite
# take many times as long as the normal ones); run it after changing a
# reader or the C API.
set -euo pipefail
cd "$(dirname "$0")/.."
flags="-fsanitize=address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer"
cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DISOFORM_BLENDER_TESTS=OFF \
  -DCMAKE_C_FLAGS="$flags" -DCMAKE_CXX_FLAGS="$flags" \
  -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined" \
  -DCMAKE_SHARED_LINKER_FLAGS="-fsanitize=address,undefined" >/dev/null
cmake --build build-asan -j"$(nproc)"

export ASAN_OPTIONS=detect_leaks=1:verify_asan_link_order=0:abort_on_error=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
export LSAN_OPTIONS=suppressions=$PWD/tests/lsan.supp
# For the interpreter; the programs built here carry the same runtime.
export LD_PRELOAD=$(gcc -print-file-name=libasan.so)
ctest --test-dir build-asan --output-on-failure -j"$(nproc)" "$@"

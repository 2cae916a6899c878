#!/usr/bin/env bash
# Builds the libFuzzer targets (clang, ASan, UBSan, coverage) and runs each
# for the given number of seconds, one after another on all cores' worth of
# jobs, starting from seed corpora made by code and keeping what each run
# finds in build-fuzz/corpus/<target> for the next run.
#
# usage: fuzz/run.sh [SECONDS_PER_TARGET] [TARGET ...]
#   default: 600 seconds, every target (vdb nrrd nifti raw ply obj stl);
#   FUZZ_JOBS=N runs N jobs at once (default: one per core)
#
# Limits per input, as docs/hostile-files.md states them for hostile files:
# 10 s, 1 GiB of memory and no single allocation over 1 GiB; leaks are
# findings too.
# A crashing, leaking or slow input is kept in build-fuzz/findings/<target>/
# and the script exits non-zero. The last line of each run gives its
# executions and coverage; build-fuzz/fuzz-summary.txt collects them.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-600}
shift || true
targets=("$@")
[ ${#targets[@]} -gt 0 ] || targets=(vdb nrrd nifti raw ply obj stl)

if ! command -v clang++ >/dev/null || ! ls /usr/lib/llvm-*/lib/clang/*/lib/linux/libclang_rt.fuzzer-x86_64.a >/dev/null 2>&1; then
  apt-get install -y clang libclang-rt-14-dev
fi
CC=clang CXX=clang++ cmake -S . -B build-fuzz -DCMAKE_BUILD_TYPE=RelWithDebInfo -DISOFORM_FUZZ=ON \
  -DISOFORM_BUILD_TESTS=OFF >/dev/null
cmake --build build-fuzz -j"$(nproc)" --target isoform_fuzz_corpus "${targets[@]/#/fuzz_}"

# This run's own seeds (several runs may go at once), removed at its end.
seeds=build-fuzz/seeds-$$
trap 'rm -rf "$seeds"' EXIT
build-fuzz/fuzz/isoform_fuzz_corpus "$seeds"

jobs=${FUZZ_JOBS:-$(nproc)}
status=0
for t in "${targets[@]}"; do
  corpus=build-fuzz/corpus/$t findings=build-fuzz/findings/$t
  mkdir -p "$corpus" "$findings"
  log=build-fuzz/fuzz-$t.log
  echo "fuzz_$t: $seconds s, $jobs jobs"
  # -fork keeps going after a finding and gives every job the same limits.
  if ! (cd "$findings" && ASAN_OPTIONS=detect_leaks=1:allocator_may_return_null=1 \
        UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
        "$OLDPWD/build-fuzz/fuzz/fuzz_$t" -fork="$jobs" -ignore_crashes=1 -ignore_timeouts=1 -ignore_ooms=1 \
        -max_total_time="$seconds" -timeout=10 -rss_limit_mb=1024 -malloc_limit_mb=1024 \
        "$OLDPWD/$corpus" "$OLDPWD/$seeds/$t") >"$log" 2>&1; then
    status=1
  fi
  summary=$(grep -E '^#[0-9]+' "$log" | tail -1 || true)
  found=$(find "$findings" -type f \( -name 'crash-*' -o -name 'leak-*' -o -name 'timeout-*' -o -name 'oom-*' \) | wc -l)
  echo "fuzz_$t $(date -u +%FT%TZ) ${seconds}s: $summary; findings: $found" | tee -a build-fuzz/fuzz-summary.txt
  [ "$found" -eq 0 ] || status=1
done
exit $status

#!/usr/bin/env bash
# Installs what the reduction benchmark needs, builds it in build-bench/
# (apart from the normal build) and runs it: isoform_reduce against
# OpenMesh's Decimater (ModQuadric + ModNormalFlipping) and meshoptimizer's
# meshopt_simplify on a ~1M-triangle graph and a ~1M-triangle headsq contour,
# at 50, 80, 90 and 99% removed, in one run; the tables go to
# docs/reduce-bench.md (bench/README.md, "Reduction").
#
#   bench/run-reduce.sh [isoform_reduce_bench options]
#
# Options go to isoform_reduce_bench (see --help): --reps N, --samples N,
# --inputs graph, --percents 90, --free-boundary, --markdown FILE, --json FILE.
# Without --markdown the tables go to docs/reduce-bench.md; without --json the
# report goes to build-bench/reduce-report.json; the printed output is also
# kept in build-bench/reduce-report.txt.
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="$root/build-bench"

packages=(cmake g++ make libopenvdb-dev libboost-iostreams-dev libtbb-dev libeigen3-dev libteem-dev
  libcli11-dev nlohmann-json3-dev libopenmesh-dev libmeshoptimizer-dev)
source "$root/bench/need-packages.sh"

cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DISOFORM_BUILD_BENCH=ON -DISOFORM_BUILD_TESTS=OFF
cmake --build "$build" -j2 --target isoform_reduce_bench

args=("$@")
[[ " ${args[*]-} " == *" --json "* ]] || args+=(--json "$build/reduce-report.json")
[[ " ${args[*]-} " == *" --markdown "* ]] || args+=(--markdown "$root/docs/reduce-bench.md")
"$build/bench/reduce/isoform_reduce_bench" "${args[@]}" | tee "$build/reduce-report.txt"

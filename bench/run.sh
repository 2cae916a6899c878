#!/usr/bin/env bash
# Installs what the benchmark needs, builds it in build-bench/ (apart from the
# normal build) and runs it: isoform's contour against OpenVDB's volumeToMesh
# and VTK's Flying Edges, in one run, printing the tables.
#
#   bench/run.sh [isoform_bench run options]
#
# Options go to `isoform_bench run` (see --help): --rounds N, --reps N,
# --no-sphere, --no-resample, --sphere-radius R, --json FILE. Without --json
# the report goes to build-bench/bench-report.json; the printed tables are
# also kept in build-bench/bench-report.txt. The real test data are read from
# ../shared/data beside the checkout, or from $ISOFORM_SHARED_DATA.
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="$root/build-bench"
data="${ISOFORM_SHARED_DATA:-$root/../shared/data}"

packages=(cmake g++ make libopenvdb-dev libboost-iostreams-dev libtbb-dev libeigen3-dev libteem-dev
  libcli11-dev nlohmann-json3-dev libvtk9-dev)
source "$root/bench/need-packages.sh"

if [[ ! -f "$data/cube.vdb" || ! -f "$data/headsq_64x64x93_u16le.raw" ]]; then
  echo "bench/run.sh: the real test data are not in $data (set ISOFORM_SHARED_DATA)" >&2
  exit 1
fi

cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DISOFORM_BUILD_BENCH=ON -DISOFORM_BUILD_TESTS=OFF
cmake --build "$build" -j2 --target isoform_bench

args=("$@")
[[ " ${args[*]-} " == *" --json "* ]] || args+=(--json "$build/bench-report.json")
"$build/bench/isoform_bench" run --data "$data" --work "$build/bench-work" "${args[@]}" |
  tee "$build/bench-report.txt"

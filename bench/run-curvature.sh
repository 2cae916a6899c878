#!/usr/bin/env bash
# Installs what the curvature benchmark needs, builds it in build-bench/
# (apart from the normal build) and runs it: isoform's surface curvature
# (default and seed's methods) against VTK's vtkCurvatures and CGAL's jet
# fitting on ~1M-vertex tori and ellipsoids, regular and jittered, in one
# run, printing the tables (bench/curvature/README.md).
#
#   bench/run-curvature.sh [isoform_curvature_bench options]
#
# Options go to isoform_curvature_bench (see --help): --reps N, --peer-reps N,
# --no-cgal4, --shapes torus, --json FILE. Without --json the report goes to
# build-bench/curvature-report.json; the printed tables are also kept in
# build-bench/curvature-report.txt.
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="$root/build-bench"

packages=(cmake g++ make libopenvdb-dev libboost-iostreams-dev libtbb-dev libeigen3-dev libteem-dev
  libcli11-dev nlohmann-json3-dev libvtk9-dev libcgal-dev)
source "$root/bench/need-packages.sh"

cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DISOFORM_BUILD_BENCH=ON -DISOFORM_BUILD_TESTS=OFF
cmake --build "$build" -j2 --target isoform_curvature_bench

args=("$@")
[[ " ${args[*]-} " == *" --json "* ]] || args+=(--json "$build/curvature-report.json")
"$build/bench/curvature/isoform_curvature_bench" "${args[@]}" | tee "$build/curvature-report.txt"

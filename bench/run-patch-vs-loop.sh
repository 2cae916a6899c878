#!/usr/bin/env bash
# Builds and runs bench/patch_vs_loop: points per second of the side-vertex
# surface against OpenSubdiv's Loop limit surface, same meshes and samples,
# one run. The meshes are contours made by the isoform command (sphere.vdb,
# and the headsq skull at 1150.5) in build-bench/patch-vs-loop/.
#
#   bench/run-patch-vs-loop.sh [--level K] [--reps N]
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="$root/build-bench"
data="${ISOFORM_SHARED_DATA:-$root/../shared/data}"
out="$build/patch-vs-loop"
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DISOFORM_BUILD_BENCH=ON -DISOFORM_BUILD_TESTS=OFF >/dev/null
cmake --build "$build" -j2 --target isoform_patch_vs_loop_bench isoform_cli
mkdir -p "$out"
iso="$build/cli/isoform"
"$iso" contour "$data/sphere.vdb" -o "$out/sphere.ply" --quiet >/dev/null
"$iso" convert "$data/headsq_64x64x93_u16le.raw" --dims 64,64,93 --type u16 --spacing 3.2,3.2,1.5 \
  -o "$out/headsq.vdb" >/dev/null
"$iso" contour "$out/headsq.vdb" --iso 1150.5 -o "$out/skull.ply" --quiet >/dev/null
for m in sphere skull; do
  "$build/bench/patch_vs_loop/isoform_patch_vs_loop_bench" "$out/$m.ply" "$@" --json "$out/$m.json"
done

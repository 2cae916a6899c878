#!/usr/bin/env bash
# The whole-process bench: installs the peers, builds isoform and the peers'
# small programs in build-bench/ (Release, apart from the normal build) and
# runs bench/process/run.py, which writes bench/RESULTS.md.
#
#   bench/run-process.sh [run.py options: --pairs N, --only JOB..., --no-sphere]
#
# The real test data are read from ../shared/data beside the checkout, or
# from $ISOFORM_SHARED_DATA; generated inputs are kept in
# build-bench/process-work (delete it to make them again).
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="$root/build-bench"
data="${ISOFORM_SHARED_DATA:-$root/../shared/data}"

packages=(cmake g++ make libopenvdb-dev libboost-iostreams-dev libtbb-dev libeigen3-dev libteem-dev
  libcli11-dev nlohmann-json3-dev libpng-dev libosd-dev libvtk9-dev libmeshoptimizer-dev libopenmesh-dev
  python3-numpy time)
source "$root/bench/need-packages.sh"

cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DISOFORM_BUILD_BENCH=ON -DISOFORM_BUILD_TESTS=OFF >/dev/null
cmake --build "$build" -j2 --target isoform_cli isoform_bench contour_openvdb contour_vtk reduce_meshopt \
  reduce_openmesh first_call
/usr/bin/python3 "$root/bench/process/run.py" --build "$build" --data "$data" --work "$build/process-work" "$@"

#!/usr/bin/env bash
# Figures 4.9 to 4.12 of the dissertation: the mean and Gaussian curvature of
# trivariate graphs shown by slicing (Section 2.3). Usage, from the checkout
# after a build: samples/curvature_slices.sh [OUT_DIR]   (default isoform-out/chapter4)
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-isoform-out/chapter4}
mkdir -p "$out"
build/samples/isoform_make_chapter4 "$out"
for fig in figure49 figure410 figure411 figure412; do
  build/cli/isoform curvature-volume "$out/$fig.vdb" -o "$out/$fig-curvature.vdb"
  for q in mean gauss; do
    build/cli/isoform slice "$out/$fig-curvature.vdb" --grid "$q" --map diverging -o "$out/$fig-$q"
  done
done
echo "pictures in $out/*-mean/ and $out/*-gauss/"

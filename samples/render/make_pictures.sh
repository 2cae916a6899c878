#!/bin/sh
# The pictures of docs/visualize.md, from the project's own samples.
# usage: samples/render/make_pictures.sh BUILD_DIR OUTPUT_DIR
# Needs blender (Debian's 3.4) on the PATH. Writes the sample volumes, the
# PLY files and the PNG pictures into OUTPUT_DIR.
set -eu
build=$1
out=$2
here=$(dirname "$0")
isoform="$build/cli/isoform"
mkdir -p "$out"
"$build/samples/isoform_make_chapter2" "$out"

render() {  # PLY PNG [render_ply.py options]
  ply=$1; png=$2; shift 2
  blender -b --factory-startup --python-exit-code 1 --python "$here/render_ply.py" -- \
    "$ply" "$png" --size 400,300 --samples 48 "$@" > "$png.log" 2>&1
  rm -f "$png.log"
  echo "rendered $png"
}

# Figures 2.2 and 2.3: domain subdivision of the three Gaussians.
"$isoform" boxes "$out/gaussians.vdb" --q 5,5,5 --gap 1 -o "$out/boxes-q5.ply"
"$isoform" boxes "$out/gaussians.vdb" --q 8,8,8 --gap 2 -o "$out/boxes-q8.ply"
render "$out/boxes-q5.ply" "$out/boxes-q5.png"
render "$out/boxes-q8.ply" "$out/boxes-q8.png"
# Figure 2.4: cos(2|x|) over part of the unit ball.
"$isoform" boxes "$out/ball.vdb" --domain spherical --q 5 --gap 2 --face-cells 6 -o "$out/ball-boxes.ply"
render "$out/ball-boxes.ply" "$out/ball-boxes.png" --view -1,0.8,-0.6
# Figures 2.5 and 2.6: transparency stacks, t = 0.5 and t = 0.95.
"$isoform" stack "$out/gaussians.vdb" --n 8 --t 0.5 --view -1,-1,-1 -o "$out/stack-t050.ply"
"$isoform" stack "$out/gaussians.vdb" --n 8 --t 0.95 --view -1,-1,-1 -o "$out/stack-t095.ply"
render "$out/stack-t050.ply" "$out/stack-t050.png" --view -1,-1,-1
render "$out/stack-t095.ply" "$out/stack-t095.png" --view -1,-1,-1
# Figures 2.7 and 2.9: slices as images and planes, and as graphs.
"$isoform" slice "$out/gaussians.vdb" --at x=0.3,y=0.5,z=0.7 --res 160 -o "$out/slices"
render "$out/slices/slice-planes.ply" "$out/slice-planes.png" --view -1,1.2,-0.8
"$isoform" slice "$out/gaussians.vdb" --at x=0.3,y=0.5,z=0.7 --res 31 --height 0.2 -o "$out/slices31"
render "$out/slices31/slice-surfaces.ply" "$out/slice-surfaces.png" --view -1,1.2,-0.8

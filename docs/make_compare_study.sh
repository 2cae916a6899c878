#!/usr/bin/env bash
# Regenerates the comparison study of docs/compare.md: sphere, torus,
# cube.vdb and the headsq skull, each reduced to 20% and 5% of its
# triangles, compared with `isoform compare` (flat triangles, Loop limit
# surface, and the side-vertex surface where the build has it).
#
# usage: docs/make_compare_study.sh [BUILD_DIR] [WORK_DIR] [SHARED_DATA_DIR]
#   defaults: build, /tmp/isoform-compare-study, ../shared/data
# Writes each study to WORK_DIR/<case>/, the tables to WORK_DIR/tables.md,
# and copies the pictures docs/compare.md shows to docs/images/compare/.
# When `isoform reduce` is not in the build, coarser grids stand in for the
# reduced meshes (same triangle fractions, roughly), and tables.md says so.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
build=${1:-build}
work=${2:-/tmp/isoform-compare-study}
data=${3:-$here/../../shared/data}
iso=$build/cli/isoform
py=/usr/bin/python3
level=${ISOFORM_STUDY_LEVEL:-6}
mkdir -p "$work" "$here/images/compare"
# Blender renders only for the cases docs/compare.md shows (they take a while).
shown="sphere-95 torus-95 cube-95 skull-80"

if "$iso" reduce --help 2>/dev/null | grep -q -- "--keep"; then have_reduce=1; else have_reduce=0; fi

# raw float volume -> VDB (level-set like: negative inside)
make_volume() {  # kind n name
  local spec
  spec=$("$py" "$here/make_compare_volume.py" "$1" "$2" "$work/$3.raw" "$data/headsq_64x64x93_u16le.raw")
  read -r dims spacing origin <<<"$spec"
  "$iso" convert "$work/$3.raw" --dims "$dims" --type f32 --spacing "$spacing" --origin "$origin" \
    -o "$work/$3.vdb" >/dev/null
}

contour() {  # volume iso out [orientation]
  "$iso" contour "$1" --iso "$2" ${4:+--orientation "$4"} -o "$3" --quiet >/dev/null
}

# base meshes: name-full.ply, then name-80.ply and name-95.ply (80% and 95% removed)
bases() {  # name full.ply coarse80.ply coarse95.ply
  if [ "$have_reduce" = 1 ]; then
    "$iso" reduce "$2" --keep 0.2 --on-surface -o "$work/$1-80.ply" >/dev/null
    "$iso" reduce "$2" --keep 0.05 --on-surface -o "$work/$1-95.ply" >/dev/null
  else
    cp "$3" "$work/$1-80.ply"
    cp "$4" "$work/$1-95.ply"
  fi
}

# sphere and torus: analytic signed distances; coarse stand-ins at 0.45 and
# 0.22 of the resolution (triangles scale with its square)
make_volume sphere 97 sphere-fine; contour "$work/sphere-fine.vdb" 0 "$work/sphere-full.ply" increasing
make_volume sphere 44 sphere-c80; contour "$work/sphere-c80.vdb" 0 "$work/sphere-c80.ply" increasing
make_volume sphere 22 sphere-c95; contour "$work/sphere-c95.vdb" 0 "$work/sphere-c95.ply" increasing
bases sphere "$work/sphere-full.ply" "$work/sphere-c80.ply" "$work/sphere-c95.ply"
make_volume torus 129 torus-fine; contour "$work/torus-fine.vdb" 0 "$work/torus-full.ply" increasing
make_volume torus 58 torus-c80; contour "$work/torus-c80.vdb" 0 "$work/torus-c80.ply" increasing
make_volume torus 29 torus-c95; contour "$work/torus-c95.vdb" 0 "$work/torus-c95.ply" increasing
bases torus "$work/torus-full.ply" "$work/torus-c80.ply" "$work/torus-c95.ply"
# cube.vdb: its contour; without reduction an analytic box at coarse grids
contour "$data/cube.vdb" 0 "$work/cube-full.ply"
make_volume box 40 cube-c80; contour "$work/cube-c80.vdb" 0 "$work/cube-c80.ply" increasing
make_volume box 20 cube-c95; contour "$work/cube-c95.vdb" 0 "$work/cube-c95.ply" increasing
make_volume box 113 cube-box
if [ "$have_reduce" = 1 ]; then cube_ref=$data/cube.vdb; else cube_ref=$work/cube-box.vdb; fi
bases cube "$work/cube-full.ply" "$work/cube-c80.ply" "$work/cube-c95.ply"
# the skull of headsq at 1150.5; without reduction the scan averaged over 2^3 and 4^3 blocks
"$iso" convert "$data/headsq_64x64x93_u16le.raw" --dims 64,64,93 --type u16 --spacing 3.2,3.2,1.5 \
  -o "$work/headsq.vdb" >/dev/null
contour "$work/headsq.vdb" 1150.5 "$work/skull-full.ply"
make_volume headsq 2 skull-c80; contour "$work/skull-c80.vdb" 1150.5 "$work/skull-c80.ply"
make_volume headsq 4 skull-c95; contour "$work/skull-c95.vdb" 1150.5 "$work/skull-c95.ply"
bases skull "$work/skull-full.ply" "$work/skull-c80.ply" "$work/skull-c95.ply"

study() {  # case mesh reference-args...
  local name=$1 mesh=$2 render=--no-render
  shift 2
  case " $shown " in *" $name "*) render= ;; esac
  "$iso" compare "$mesh" "$@" --level "$level" $render --quiet --json -o "$work/$name" >"$work/$name.json"
}
for f in 80 95; do
  study sphere-$f "$work/sphere-$f.ply" --reference sphere --centre 0,0,0 --radius 1
  study torus-$f "$work/torus-$f.ply" --reference torus --centre 0,0,0 --radius 1 --minor-radius 0.4
  study cube-$f "$work/cube-$f.ply" --reference "$cube_ref" --iso 0
  study skull-$f "$work/skull-$f.ply" --reference "$work/headsq.vdb" --iso 1150.5
done

"$py" "$here/compare_tables.py" "$work" "$have_reduce" >"$work/tables.md"
for c in $shown; do
  for p in curvature-histograms deviation; do
    [ -f "$work/$c/$p.png" ] && cp "$work/$c/$p.png" "$here/images/compare/$c-$p.png"
  done
  for r in "$work/$c"/render-*.png; do
    case "$c:$r" in cube*isophotes* | skull*isophotes*) continue ;; esac
    [ -f "$r" ] && cp "$r" "$here/images/compare/$c-$(basename "$r")"
  done
done
echo "wrote $work/tables.md"

#!/usr/bin/env bash
# The regression set of the command-line tool: scripts/regression.sh TOOL DATA OUT [SHARED]
# runs TOOL (a built distortion_optimizer) on 2D and 3D cases (every schedule, global step and
# parallel sweep, 1 and 2 threads, border fixed and free, untangling, subdivision, volume mode,
# carried surfaces, ideal reference) and writes each case's outputs and report into OUT, with the
# report's timings removed. Two builds' OUT folders compared with `diff -r` show whether a change
# kept every output bit-identical. DATA is a build's data folder (build/data, from libcgal-demo);
# SHARED, if given, is ../shared/data (the ABCD cases), which adds the untangling of published
# starts. Each case runs with --quiet; a case that fails records its exit status in OUT/status.
set -uo pipefail

if [ "$#" -lt 3 ]; then
  echo "usage: $0 TOOL DATA OUT [SHARED]" >&2
  exit 2
fi
TOOL=$1 DATA=$2 OUT=$3 SHARED=${4:-}
mkdir -p "$OUT"
: > "$OUT/status"
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)

# case NAME OUTPUT-EXTENSION ARGS...: one run of the tool into OUT/NAME.*
case_() {
  local name=$1 ext=$2; shift 2
  "$TOOL" "$@" --output "$OUT/$name.$ext" --report "$OUT/$name.json" --quiet > /dev/null 2> "$OUT/$name.err"
  echo "$name $?" >> "$OUT/status"
  [ -f "$OUT/$name.json" ] && sed -i '/seconds"/d' "$OUT/$name.json"
}

lion=$DATA/lion-head.off
case_ sd_fixed obj --source "$lion" --measure symmetric_dirichlet --svg "$OUT/sd_fixed.svg"
case_ sd_free obj --source "$lion" --measure symmetric_dirichlet --fix none
case_ sd_free_t2 obj --source "$lion" --measure symmetric_dirichlet --fix none --threads 2
case_ conformal_local obj --source "$lion" --measure conformal --schedule local --iterations 20
case_ conformal_global obj --source "$lion" --measure conformal --schedule global --iterations 20
case_ arap_laplacian obj --source "$lion" --measure arap --global-step laplacian
case_ mips_sets_t2 obj --source "$lion" --measure mips --threads 2 --parallel-sweep sets
case_ mips_partition_t2 obj --source "$lion" --measure mips --threads 2 --parallel-sweep partition
case_ condition_bfgs obj --source "$DATA/mushroom.off" --measure condition --solver bfgs --iterations 20
case_ isometric_greedy obj --source "$DATA/mushroom.off" --measure isometric --order greedy --cell-weighting uniform
case_ subdivided obj --source "$DATA/mushroom.off" --measure symmetric_dirichlet --subdivide 1 --scheme loop \
  --subdivided-source "$OUT/subdivided_source.off"

awk -v k=8 -f "$here/demo_cube.awk" > "$OUT/cube_input.mesh"
case_ cube_radial mesh --source "$OUT/cube_input.mesh" --start radial --center 0,0,0 --boundary fixed --measure conformal
case_ cube_radial_t2 mesh --source "$OUT/cube_input.mesh" --start radial --center 0,0,0 --boundary fixed --measure conformal --threads 2
case_ cube_radial_sd_laplacian mesh --source "$OUT/cube_input.mesh" --start radial --center 0,0,0 --measure symmetric_dirichlet \
  --global-step laplacian --iterations 30
case_ cube_ball mesh --source "$OUT/cube_input.mesh" --start ball --measure isometric --iterations 30
case_ blobby_ball mesh --source "$DATA/blobby.off" --start ball --cell-size 0.08 --measure symmetric_dirichlet \
  --mesh-output "$OUT/blobby_mesh3.mesh" --iterations 20
case_ blobby_quality mesh --source "$OUT/blobby_mesh3.mesh" --reference ideal --boundary slide --measure conformal --iterations 20
case_ cube_to_target mesh --source "$OUT/cube_input.mesh" --target "$OUT/cube_radial.mesh" --measure arap --fix none --iterations 20

if [ -n "$SHARED" ]; then
  case_ elephant_untangle obj --source "$SHARED/abcd/elephant_2K_source.obj" --target "$SHARED/abcd/elephant_2K_target.obj" \
    --untangle --measure symmetric_dirichlet
  case_ octopus_untangle_free obj --source "$SHARED/abcd/octopus_6K_surface.obj" --target "$SHARED/abcd/octopus_6K_initial_uv.obj" \
    --untangle --fix none --measure symmetric_dirichlet
  case_ bar_untangle mesh --source "$SHARED/abcd/twisted_bar_12K_source.mesh" --target "$SHARED/abcd/twisted_bar_12K_target.mesh" \
    --untangle --measure symmetric_dirichlet --iterations 20
fi

#!/usr/bin/env bash
# The command-line tool's wall time, as a user runs it on a source/target pair of Medit files:
# reading both, building the complex, optimizing, writing the result. The pair is the radial map
# x|x| of Table 1 on the cube [-1, 1]^3 meshed by the tool itself (CGAL Mesh_3, --cell-size,
# written by a run of 0 iterations); the boundary is fixed and the measure is K (the tool's
# defaults), and again under K's own projected Newton steps (--global-step newton). Then the
# exponential stretch (x, y, z) -> (exp(2x), y, z) of the same cube under MIPS and symmetric
# Dirichlet (untangled first: the stretch flattens a few slivers). Each case runs on one thread
# and on two, interleaved, `repeats` times: the table gives the median wall time, the
# optimization's own seconds (from the report), its iterations and the final energy; last, the 2-thread
# speedup of the median wall times.
#
#   bash benchmark/Distortion_optimization/bench_tool.sh [cell_size [repeats]]
#   (default cell size 0.0875: about 54K tetrahedra; run after scripts/test.sh)
source "$(dirname "${BASH_SOURCE[0]}")/tool_common.sh"
CELL=${1:-0.0875}
REPEATS=${2:-3}

make_cube_pairs "$CELL"
echo "cube [-1,1]^3, Mesh_3 cell size $CELL: $(awk '/^Tetrahedra/ { getline; print; exit }' "$OUT/source.mesh") tetrahedra"

printf '%-26s %7s %10s %12s %6s %14s\n' case threads "wall s" "optimize s" iters "final E"
median() { sort -g | awk '{ v[NR] = $1 } END { print v[int((NR + 1) / 2)] }'; }
bench() {
  local name=$1; shift
  local -A walls optimize energy iterations
  for ((r = 0; r < REPEATS; ++r)); do
    for threads in 1 2; do
      local report=$OUT/$name-$threads.json start end
      start=$(date +%s.%N)
      "$TOOL" --source "$OUT/source.mesh" "$@" --threads "$threads" --quiet --report "$report" --output "$OUT/out.mesh" > /dev/null
      end=$(date +%s.%N)
      walls[$threads]+="$(awk -v a="$start" -v b="$end" 'BEGIN { print b - a }') "
      optimize[$threads]+="$(field "$report" seconds) "
      energy[$threads]=$(field "$report" final_energy)
      iterations[$threads]=$(field "$report" sweeps)
    done
  done
  local w1 w2
  for threads in 1 2; do
    local w o
    w=$(tr ' ' '\n' <<< "${walls[$threads]}" | grep . | median)
    o=$(tr ' ' '\n' <<< "${optimize[$threads]}" | grep . | median)
    printf '%-26s %7s %10.3f %12.3f %6s %14.8g\n' "$name" "$threads" "$w" "$o" "${iterations[$threads]}" "${energy[$threads]}"
    if [ "$threads" = 1 ]; then w1=$w; else w2=$w; fi
  done
  printf '%-26s %7s %10.2f\n' "$name" speedup "$(awk -v a="$w1" -v b="$w2" 'BEGIN { print a / b }')"
}
bench "radial, K, fixed" --target "$OUT/radial.mesh"
bench "radial, K, own Newton" --target "$OUT/radial.mesh" --global-step newton
bench "stretch, MIPS, fixed" --target "$OUT/stretch.mesh" --measure mips --untangle
bench "stretch, SD, fixed" --target "$OUT/stretch.mesh" --measure symmetric_dirichlet --untangle

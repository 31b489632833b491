#!/usr/bin/env bash
# What the stopping rule's threshold costs and spares (the manual's "Stopping Rule"). Each case
# runs the tool once with --threshold 0 up to a cap of iterations, and the report's energy after
# each iteration gives, for thresholds 1e-4 (the default), 1e-3 and 1e-2, the iteration at which
# the rule
#     E_{k-1} - E_k <= threshold * |E_{k-1} - m|     (m: the measure's value on rigid maps)
# would have stopped the same run, and how far above the lowest energy of the whole run it stops
# there (in percent). The runs are deterministic, so a run stopped by the rule is this run's start
# (under the default schedule of Newton's steps alone, such a run also sweeps once before it stops:
# its energy is then a little lower).
# Cases: the radial and stretched 54K cubes of bench_tool.sh; libcgal-demo's disks (Tutte start,
# border fixed or free); the volume mode (cube and blobby onto the ball, boundary sliding on the
# sphere; helmet, hand and dino by the radial map, sliding on their own surface: the slow tails).
#
#   bash benchmark/Distortion_optimization/bench_stopping.sh [threads (default 2)]
#   (run after scripts/test.sh; the disks and surfaces come from build/data, which
#   scripts/extract_data.sh fills from libcgal-demo; about 3 minutes on two threads)
source "$(dirname "${BASH_SOURCE[0]}")/tool_common.sh"
THREADS=${1:-2}
DATA=$ROOT/build/data
bash "$ROOT/scripts/extract_data.sh" "$DATA" > /dev/null
make_cube_pairs 0.0875

printf '%-30s %5s %12s %19s %19s %19s\n' case iters "lowest E" "1e-4: stop, above" "1e-3: stop, above" "1e-2: stop, above"
# case NAME FLOOR CAP TOOL_ARGUMENTS...
case_() {
  local name=$1 floor=$2 cap=$3 report=$OUT/report.json
  shift 3
  if ! "$TOOL" "$@" --threshold 0 --iterations "$cap" --threads "$THREADS" --quiet --report "$report" \
      > /dev/null 2> "$OUT/log"; then
    echo "$name: failed: $(tail -1 "$OUT/log")"
    return
  fi
  # The energies E_0 (after the harmonic start) .. E_N, one per line.
  { field "$report" harmonic_start_energy
    sed -n 's/^  "energy_per_sweep": \[\(.*\)\].*/\1/p' "$report" | tr ',' '\n'; } |
  awk -v name="$name" -v m="$floor" '
    { e[n++] = $1 + 0 }
    END {
      lowest = e[0]
      for(k = 1; k < n; ++k) if(e[k] < lowest) lowest = e[k]
      line = sprintf("%-30s %5d %12.7f", name, n - 1, lowest)
      split("1e-4 1e-3 1e-2", thresholds, " ")
      for(t = 1; t <= 3; ++t) {
        eps = thresholds[t] + 0; stop = -1
        for(k = 1; k < n && stop < 0; ++k) {
          above = e[k - 1] - m; if(above < 0) above = -above
          if(!(e[k - 1] - e[k] > eps * above)) stop = k
        }
        line = line (stop < 0 ? sprintf(" %19s", "not by the cap") : sprintf(" %8d %+9.4f%%", stop, 100 * (e[stop] / lowest - 1)))
      }
      print line
    }'
}
case_ "radial cube, K" 1 40 --source "$OUT/source.mesh" --target "$OUT/radial.mesh" --output "$OUT/o.mesh"
case_ "stretched cube, MIPS" 3 30 --source "$OUT/source.mesh" --target "$OUT/stretch.mesh" --measure mips --untangle --output "$OUT/o.mesh"
case_ "stretched cube, SD" 1 30 --source "$OUT/source.mesh" --target "$OUT/stretch.mesh" --measure symmetric_dirichlet --untangle --output "$OUT/o.mesh"
for disk in lion-head mannequin-devil; do
  case_ "$disk, SD" 1 60 --source "$DATA/$disk.off" --measure symmetric_dirichlet --output "$OUT/o.off"
  case_ "$disk, SD, free" 1 60 --source "$DATA/$disk.off" --measure symmetric_dirichlet --fix none --output "$OUT/o.off"
done
case_ "lion-head, K" 1 60 --source "$DATA/lion-head.off" --output "$OUT/o.off"
case_ "nefertiti, K" 1 60 --source "$DATA/nefertiti.off" --output "$OUT/o.off"
case_ "mushroom, C" 1 60 --source "$DATA/mushroom.off" --measure isometric --output "$OUT/o.off"
case_ "cube to ball, C" 1 80 --source "$OUT/cube.off" --start ball --measure isometric --output "$OUT/o.mesh"
case_ "blobby to ball, K" 1 80 --source "$DATA/blobby.off" --start ball --output "$OUT/o.mesh"
case_ "blobby to ball, SD" 1 80 --source "$DATA/blobby.off" --start ball --measure symmetric_dirichlet --output "$OUT/o.mesh"
for surface in helmet hand dino; do
  case_ "$surface, radial, K" 1 150 --source "$DATA/$surface.off" --start radial --boundary slide --output "$OUT/o.mesh"
done

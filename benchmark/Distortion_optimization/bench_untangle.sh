#!/usr/bin/env bash
# Untangling real tangled maps, then optimizing, through the command-line tool (its --untangle
# contract): the cases of the ABCD paper (Naitsat, Zhu, Zeevi 2020) in ../shared/data/abcd. For each
# case: inverted cells before and after, the untangling time and rounds, the time of the
# optimization that follows, and the final energy (K for tetrahedra, symmetric Dirichlet for
# triangles). Anchored vertices (the *_anchors.txt files) are fixed; the planar and UV cases have a
# free boundary: the elephants' boundaries cross (the tool then warns and runs without the guard),
# the octopus UV's does not (the guard keeps it so; the guarded rounds leave ears inverted and the
# untangler starts again from Tutte's embedding). Then CGAL's ARAP parameterizations of lion-head
# and mannequin-devil (border free, made by the untangle_parameterization example; 330 and 2,673
# triangles flipped), untangled with the border fixed and free. Last, the unit square's 61 x 61 grid
# (7,442 triangles) with its border fixed on an L-shaped domain and four starts of its inside
# (lshape_grid.awk: left in place, mirrored, random, collapsed).
#
#   bash benchmark/Distortion_optimization/bench_untangle.sh [data_dir [threads]]
#   (default data dir: ../shared/data/abcd beside the repository; run after scripts/test.sh)
source "$(dirname "${BASH_SOURCE[0]}")/tool_common.sh"
DATA=${1:-$ROOT/../shared/data/abcd}
THREADS=${2:-1}
[ -d "$DATA" ] || { echo "no data folder $DATA" >&2; exit 1; }

printf '%-31s %7s %9s %9s %8s %10s %10s %8s %12s\n' case cells "inv start" "inv end" rounds "untangle s" "optimize s" sweeps "final E"
run() {
  local name=$1; shift
  local report=$OUT/$name.json
  if "$TOOL" "$@" --untangle --threads "$THREADS" --report "$report" > "$OUT/$name.log" 2>&1; then
    local seconds untangle
    seconds=$(field "$report" seconds); untangle=$(field "$report" untangle_seconds)
    printf '%-31s %7s %9s %9s %8s %10.3f %10.3f %8s %12.6g\n' "$name" "$(field "$report" cells)" \
      "$(field "$report" inverted_start_cells)" "$(field "$report" inverted_cells)" "$(field "$report" untangle_iterations)" \
      "$untangle" "$(awk -v a="$seconds" -v b="$untangle" 'BEGIN { print a - b }')" "$(field "$report" sweeps)" \
      "$(field "$report" final_energy)"
  else
    printf '%-31s failed: %s\n' "$name" "$(tail -1 "$OUT/$name.log")"
  fi
}

run twisted_bar_30K --source "$DATA/twisted_bar_30K_source.mesh" --target "$DATA/twisted_bar_30K_target.mesh" \
  --fix "$DATA/twisted_bar_30K_anchors.txt" --measure conformal --output "$OUT/bar30.mesh"
run wrench_bent_50K --source "$DATA/wrench_bent_50K_source.mesh" --target "$DATA/wrench_bent_50K_target.mesh" \
  --fix "$DATA/wrench_bent_50K_anchors.txt" --measure conformal --output "$OUT/wrench.mesh"
run twisted_bar_12K --source "$DATA/twisted_bar_12K_source.mesh" --target "$DATA/twisted_bar_12K_target.mesh" \
  --measure conformal --output "$OUT/bar12.mesh"
for size in 2K 30K; do
  run "elephant_$size" --source "$DATA/elephant_${size}_source.obj" --target "$DATA/elephant_${size}_target.obj" \
    --fix none --measure symmetric_dirichlet --output "$OUT/elephant_$size.obj"
done
run octopus_6K_uv --source "$DATA/octopus_6K_surface.obj" --target "$DATA/octopus_6K_initial_uv.obj" \
  --fix none --measure symmetric_dirichlet --output "$OUT/octopus.obj"
EXAMPLE=$ROOT/build/examples/Distortion_optimization/untangle_parameterization
for disk in lion-head mannequin-devil; do
  (cd "$OUT" && "$EXAMPLE" "$ROOT/build/data/$disk.off" "$disk" symmetric_dirichlet > /dev/null)
  for fix in boundary none; do
    run "${disk}_arap_$fix" --source "$OUT/${disk}_arap.obj" --target "$OUT/${disk}_arap.obj" --fix "$fix" \
      --measure symmetric_dirichlet --output "$OUT/$disk.obj"
  done
done
awk -v n=61 -v start=source -f "$ROOT/benchmark/Distortion_optimization/lshape_grid.awk" > "$OUT/lshape_source.obj"
for start in grid mirrored random collapsed; do
  awk -v n=61 -v start=$start -f "$ROOT/benchmark/Distortion_optimization/lshape_grid.awk" > "$OUT/lshape_$start.obj"
  run "lshape_$start" --source "$OUT/lshape_source.obj" --target "$OUT/lshape_$start.obj" --measure symmetric_dirichlet \
    --output "$OUT/lshape.obj"
done

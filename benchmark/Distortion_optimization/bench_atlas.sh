#!/usr/bin/env bash
# Atlases of CGAL's closed, handled and holed surfaces through the command-line tool (no --target:
# compute_atlas()), under symmetric Dirichlet, one thread: charts, cones, the seams' share of the
# edge length, packing efficiency, area-weighted mean and largest per-face energy, inverted faces
# and overlapping charts (both must be 0), and seconds. The issue's reference (xatlas, measured by
# an independent checker): mean SD camel 1.61, homer 1.11, armadillo 1.11, lion 1.11, holes 1.003,
# elephant-with-holes 1.02; seams 8.2, 7.5, 6.0, 4.0, 0.75, 8.5 % of the edge length. The
# bounded runs (name:bound) cut a piece above the bound into charts of nearly constant normal.
#
#   bash benchmark/Distortion_optimization/bench_atlas.sh [threads]
#   (the surfaces are read from libcgal-dev's data.tar.gz; run after scripts/test.sh)
source "$(dirname "${BASH_SOURCE[0]}")/tool_common.sh"
THREADS=${1:-1}
TARBALL=${CGAL_DOC_DIR:-/usr/share/doc/libcgal-dev}/data.tar.gz
SURFACES="camel homer armadillo lion holes elephant elephant-with-holes eight knot1 sphere"
# Runs with a distortion bound (--max-distortion): the surface, then the bound.
BOUNDED="homer:1.05 lion:1.01 elephant-with-holes:1.005"
members=()
for s in $SURFACES; do members+=("data/meshes/$s.off"); done
tar -xzf "$TARBALL" -C "$OUT" "${members[@]}"

printf '%-20s %6s %6s %5s %7s %7s %9s %9s %4s %4s %8s\n' surface faces charts cones "seam %" packing "mean SD" "max SD" inv ovl seconds
for run in $SURFACES $BOUNDED; do
  s=${run%%:*} bound=${run#*:} options=() name=$run
  [ "$bound" = "$run" ] && bound= || options=(--max-distortion "$bound")
  report=$OUT/$s$bound.json
  if "$TOOL" --source "$OUT/data/meshes/$s.off" --output "$OUT/$s.obj" --measure symmetric_dirichlet --threads "$THREADS" \
       "${options[@]}" --report "$report" > "$OUT/$s.log" 2>&1; then
    printf '%-20s %6s %6s %5s %7.2f %7.3f %9.4f %9.3f %4s %4s %8.2f\n' "$name" "$(field "$report" cells)" "$(field "$report" charts)" \
      "$(field "$report" cones)" "$(awk -v x="$(field "$report" seam_length_fraction)" 'BEGIN { print 100 * x }')" \
      "$(field "$report" packing_efficiency)" "$(field "$report" final_energy)" "$(field "$report" max_cell_distortion)" \
      "$(field "$report" inverted_cells)" "$(field "$report" overlapping_charts)" "$(field "$report" seconds)"
  else
    printf '%-20s failed: %s\n' "$name" "$(tail -1 "$OUT/$s.log")"
  fi
done

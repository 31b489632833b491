#!/usr/bin/env bash
# The guarded sliding boundary through the command-line tool, as a user meets it on a volume that
# is not star-shaped: `--source S.off --start radial --boundary slide` meshes the interior of a
# closed surface with CGAL Mesh_3, maps it by the radial map x|x| of Table 1, and minimizes K with
# the boundary vertices sliding on the surface itself and kept from crossing it (the boundary
# guard). Per surface: tetrahedra and sliding vertices, the meshing time, the optimization's time
# (median of `repeats` runs; untangling included), its iterations and the final K.
#
#   bash benchmark/Distortion_optimization/bench_sliding.sh [repeats [threads [surface.off ...]]]
#   (default: 1 repeat, 1 thread, helmet, hand and dino from libcgal-demo's data.tar.gz, which
#   scripts/extract_data.sh puts in build/data; run after scripts/test.sh)
source "$(dirname "${BASH_SOURCE[0]}")/tool_common.sh"
REPEATS=${1:-1}
THREADS=${2:-1}
shift $(($# < 2 ? $# : 2))
SURFACES=("$@")
if [ "${#SURFACES[@]}" -eq 0 ]; then
  bash "$ROOT/scripts/extract_data.sh" "$ROOT/build/data" > /dev/null
  SURFACES=("$ROOT"/build/data/{helmet,hand,dino}.off)
  for surface in "${SURFACES[@]}"; do
    [ -r "$surface" ] || { echo "no $surface (install libcgal-demo) and no surface given" >&2; exit 1; }
  done
fi

printf '%-10s %7s %8s %7s %7s %11s %6s %10s\n' surface threads tets sliding "mesh s" "optimize s" iters "final K"
median() { sort -g | awk '{ v[NR] = $1 } END { print v[int((NR + 1) / 2)] }'; }
for surface in "${SURFACES[@]}"; do
  name=$(basename "$surface" .off)
  report=$OUT/$name.json
  seconds=()
  for ((r = 0; r < REPEATS; ++r)); do
    if ! "$TOOL" --source "$surface" --start radial --boundary slide --threads "$THREADS" \
        --quiet --report "$report" --output "$OUT/out.mesh" > /dev/null 2> "$OUT/$name.log"; then
      echo "$name: failed: $(tail -1 "$OUT/$name.log")"
      continue 2
    fi
    seconds+=("$(field "$report" seconds)")
  done
  printf '%-10s %7s %8s %7s %7.2f %11.2f %6s %10.6f\n' "$name" "$THREADS" "$(field "$report" tets)" \
    "$(field "$report" boundary_vertices)" "$(field "$report" mesh_seconds)" "$(printf '%s\n' "${seconds[@]}" | median)" \
    "$(field "$report" sweeps)" "$(field "$report" final_energy)"
done

#!/usr/bin/env bash
# The demo: what the package is for, on real meshes shipped by Debian's libcgal-demo, through the
# command-line tool and one example. Builds them (Release, build/), then runs, each in seconds:
#   1-2. a disk (lion-head) parametrized: Tutte start, then symmetric Dirichlet, border fixed / free;
#   3.   CGAL's own ARAP parameterization of it, with flipped triangles, untangled then optimized;
#   4.   the paper's Table 1 map: a regular cube mesh, radial start x|x|, K, boundary fixed;
#   5.   closed surfaces (a cube: the paper's Fig. 13, and blobby) meshed by CGAL Mesh_3 and mapped
#        onto the unit ball, the boundary sliding on the sphere;
#   6.   the quality of the cube's Mesh_3 mesh improved (ideal tetrahedra, boundary sliding).
# Prints a table of energies, inverted cells and times, and the pictures it wrote (build/demo/).
#   bash scripts/demo.sh             build, then run
#   bash scripts/demo.sh --no-build  run with what is built (DEMO_BUILD_DIR, default build)
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

BUILD=${DEMO_BUILD_DIR:-build}
if [ "${1:-}" != "--no-build" ]; then
  bash scripts/install_dependencies.sh
  bash scripts/configure.sh "$BUILD" -DBUILD_EXAMPLES=ON
  cmake --build "$BUILD" --target distortion_optimizer untangle_parameterization -j2
fi
BIN=$BUILD/bin
EXAMPLES=$BUILD/examples/Distortion_optimization
DATA=$BUILD/data
OUT=$BUILD/demo
mkdir -p "$OUT"
for mesh in lion-head.off blobby.off; do
  [ -s "$DATA/$mesh" ] || { echo "demo: $DATA/$mesh is missing (install libcgal-demo, then re-run cmake)" >&2; exit 1; }
done

# A value of the tool's JSON report.
field() { sed -n "s/^  \"$2\": \([^,]*\),\{0,1\}$/\1/p" "$1"; }
rows=()
# run NAME JSON ARGS...: runs the tool, keeps a row of the table, fails if a cell stays inverted.
run() {
  local name=$1 json=$2; shift 2
  "$BIN/distortion_optimizer" "$@" --report "$json" --quiet > /dev/null
  [ "$(field "$json" inverted_cells)" = 0 ] || { echo "demo: $name left inverted cells" >&2; exit 1; }
  rows+=("$(printf '%-44s %8s %10.5g %10.5g %9s %8.2f' "$name" "$(field "$json" cells)" \
    "$(field "$json" initial_energy)" "$(field "$json" final_energy)" \
    "$(field "$json" inverted_start_cells)" "$(field "$json" seconds)")")
}

echo "== 1-2. lion-head: Tutte start, then symmetric Dirichlet (border fixed, then free)"
run "lion-head SD, border fixed (Tutte start)" "$OUT/lion-head_fixed.json" --source "$DATA/lion-head.off" \
  --output "$OUT/lion-head_fixed.obj" --measure symmetric_dirichlet \
  --svg "$OUT/lion-head_fixed.svg" --svg-both --energy-plot "$OUT/lion-head_fixed_energy.svg"
run "lion-head SD, border free (Tutte start)" "$OUT/lion-head_free.json" --source "$DATA/lion-head.off" \
  --output "$OUT/lion-head_free.obj" --measure symmetric_dirichlet --fix none --svg "$OUT/lion-head_free.svg"

echo "== 3. lion-head: CGAL's ARAP parameterization, untangled, then symmetric Dirichlet (border free)"
"$EXAMPLES/untangle_parameterization" "$DATA/lion-head.off" "$OUT/lion-head"

echo "== 4. the paper's Table 1: a cube of 48000 tetrahedra, radial start x|x|, K, boundary fixed"
awk -v k=20 -f scripts/demo_cube.awk > "$OUT/cube.mesh"
run "cube radial map, K, boundary fixed" "$OUT/cube_radial.json" --source "$OUT/cube.mesh" --start radial \
  --center 0,0,0 --boundary fixed --measure conformal --output "$OUT/cube_radial.mesh" \
  --svg "$OUT/cube_radial.svg" --svg-both --energy-plot "$OUT/cube_radial_energy.svg"

echo "== 5. closed surfaces meshed by CGAL Mesh_3, mapped onto the unit ball, boundary sliding on the sphere"
printf 'OFF\n8 12 0\n-1 -1 -1\n1 -1 -1\n1 1 -1\n-1 1 -1\n-1 -1 1\n1 -1 1\n1 1 1\n-1 1 1\n%s\n' \
  "3 0 2 1
3 0 3 2
3 4 5 6
3 4 6 7
3 0 1 5
3 0 5 4
3 1 2 6
3 1 6 5
3 2 3 7
3 2 7 6
3 3 0 4
3 3 4 7" > "$OUT/cube.off"
run "cube -> ball (Fig. 13), isometric, sliding" "$OUT/cube_ball.json" --source "$OUT/cube.off" --start ball \
  --measure isometric --output "$OUT/cube_ball.mesh" --mesh-output "$OUT/cube_mesh3.mesh" \
  --svg "$OUT/cube_ball.svg" --svg-both
run "blobby -> ball, SD, sliding" "$OUT/blobby_ball.json" --source "$DATA/blobby.off" --start ball \
  --measure symmetric_dirichlet --output "$OUT/blobby_ball.mesh" --svg "$OUT/blobby_ball.svg" --svg-both

echo "== 6. the cube's Mesh_3 mesh, quality improved (ideal tetrahedra, K, boundary sliding)"
run "cube Mesh_3 mesh quality (ideal tets, K)" "$OUT/cube_quality.json" --source "$OUT/cube_mesh3.mesh" \
  --reference ideal --boundary slide --measure conformal --output "$OUT/cube_improved.mesh" \
  --svg "$OUT/cube_quality.svg" --svg-both
q=$OUT/cube_quality.json
printf '   min dihedral %.1f -> %.1f degrees, slivers (< 10 degrees) %s -> %s, mean radius ratio %.3f -> %.3f\n' \
  "$(field "$q" min_dihedral_before)" "$(field "$q" min_dihedral_after)" "$(field "$q" slivers_before)" \
  "$(field "$q" slivers_after)" "$(field "$q" mean_radius_ratio_before)" "$(field "$q" mean_radius_ratio_after)"

echo
printf '%-44s %8s %10s %10s %9s %8s\n' "run (tool)" cells start final "inverted" seconds
printf '%-44s %8s %10s %10s %9s %8s\n' "" "" energy energy "at start" ""
printf '%s\n' "${rows[@]}"
echo
echo "Pictures (each cell coloured by its distortion; red: inverted):"
ls -1 "$OUT"/*.svg

# Sourced by the benchmark scripts that run the command-line tool: the repository root, the tool
# (built by scripts/test.sh), a temporary folder removed on exit, and `field REPORT KEY`, one
# value of a report written by --report.
set -euo pipefail
ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
TOOL=$ROOT/build/bin/distortion_optimizer
[ -x "$TOOL" ] || { echo "build the tool first (bash scripts/test.sh)" >&2; exit 1; }
OUT=$(mktemp -d)
trap 'rm -rf "$OUT"' EXIT

field() { sed -n "s/^  \"$2\": \\(.*\\),\\?$/\\1/p" "$1" | sed 's/,$//' | head -1; }

# The pairs of bench_tool.sh and bench_stopping.sh: the cube [-1, 1]^3 meshed by the tool (CGAL
# Mesh_3, cell size $1) in $OUT/source.mesh, its radial map x|x| of Table 1 in $OUT/radial.mesh
# (written by a run of 0 iterations) and its exponential stretch (x, y, z) -> (exp(2x), y, z) in
# $OUT/stretch.mesh; $OUT/cube.off is the cube's surface.
make_cube_pairs() {
cat > "$OUT/cube.off" <<'EOF'
OFF
8 12 0
-1 -1 -1
1 -1 -1
-1 1 -1
1 1 -1
-1 -1 1
1 -1 1
-1 1 1
1 1 1
3 0 2 1
3 1 2 3
3 4 5 6
3 5 7 6
3 0 1 4
3 1 5 4
3 2 6 3
3 3 6 7
3 0 4 2
3 2 4 6
3 1 3 5
3 3 7 5
EOF
"$TOOL" --source "$OUT/cube.off" --start radial --center 0,0,0 --cell-size "$1" --iterations 0 --quiet \
  --mesh-output "$OUT/source.mesh" --output "$OUT/radial.mesh" > /dev/null
# The stretch of the source's vertices (the Medit vertex lines: x y z label).
awk '/^Vertices/ { print; getline; print; n = $1; next }
     n > 0 { printf "%.17g %s %s %s\n", exp(2 * $1), $2, $3, $4; --n; next } { print }' "$OUT/source.mesh" > "$OUT/stretch.mesh"
}

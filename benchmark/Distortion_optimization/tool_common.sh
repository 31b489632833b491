# Sourced by the benchmark scripts that run the command-line tool: the repository root, the tool
# (built by scripts/test.sh), a temporary folder removed on exit, and `field REPORT KEY`, one
# value of a report written by --report.
set -euo pipefail
ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
TOOL=$ROOT/build/examples/Distortion_optimization/distortion_optimizer
[ -x "$TOOL" ] || { echo "build the tool first (bash scripts/test.sh)" >&2; exit 1; }
OUT=$(mktemp -d)
trap 'rm -rf "$OUT"' EXIT

field() { sed -n "s/^  \"$2\": \\(.*\\),\\?$/\\1/p" "$1" | sed 's/,$//' | head -1; }

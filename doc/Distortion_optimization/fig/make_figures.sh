#!/usr/bin/env bash
# Regenerates the manual's and the README's pictures from the demo's output: runs
# scripts/demo.sh on what is built (build/, or DEMO_BUILD_DIR), then copies the small SVGs and
# converts the large ones (tens of thousands of cells) to PNG with rsvg-convert (Debian package
# librsvg2-bin; only this script needs it). From the repository root:
#   bash doc/Distortion_optimization/fig/make_figures.sh
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/../../.."
command -v rsvg-convert > /dev/null || { echo "make_figures: rsvg-convert not found (apt-get install librsvg2-bin)" >&2; exit 1; }
bash scripts/demo.sh --no-build
DEMO=${DEMO_BUILD_DIR:-build}/demo
FIG=doc/Distortion_optimization/fig
for name in cube_radial cube_radial_energy lion-head_fixed_energy cube_ball cube_quality; do
  cp "$DEMO/$name.svg" "$FIG/$name.svg"
done
for name in lion-head_fixed lion-head_arap lion-head_optimized; do
  rsvg-convert -w 640 "$DEMO/$name.svg" -o "$FIG/$name.png"
done
echo "make_figures: pictures written to $FIG"

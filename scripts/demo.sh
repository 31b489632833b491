#!/usr/bin/env bash
# Builds (Release, build/) and runs the Distortion_optimization demo. Works from any directory.
# Extra arguments are passed to the demo.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

bash scripts/install_dependencies.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DBUILD_EXAMPLES=ON
cmake --build build --target distortion_demo -j2
exec build/examples/Distortion_optimization/distortion_demo "$@"

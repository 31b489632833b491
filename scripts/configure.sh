#!/usr/bin/env bash
# Configures a Release build of the package: scripts/configure.sh BUILD_DIR [cmake options...].
# A new build folder gets Ninja when it is installed: its objects compile while the libraries they
# link are still compiling (make waits for each library first), which keeps both cores busy.
# A folder already configured keeps its generator.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

build=$1
shift
generator=()
if [ ! -f "$build/CMakeCache.txt" ] && command -v ninja >/dev/null 2>&1; then
  generator=(-G Ninja)
fi
cmake -S . -B "$build" "${generator[@]}" -DCMAKE_BUILD_TYPE=Release "$@"

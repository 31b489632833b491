#!/usr/bin/env bash
# Builds the benchmarks (Release, build/, with the tool and the examples) and, given a name, runs
# that benchmark with the arguments that follow, from the repository root:
#   bash scripts/bench.sh                        build them all
#   bash scripts/bench.sh bench_volume 5         build, then run build/benchmark/.../bench_volume 5
# The tests' build (scripts/test.sh) leaves them out: they compile for about seven minutes of CPU
# and assert nothing.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

bash scripts/install_dependencies.sh
bash scripts/configure.sh build -DBUILD_BENCHMARKS=ON
if [ $# -eq 0 ]; then
  cmake --build build -j2
  exit 0
fi
name=$1; shift
cmake --build build --target "$name" -j2
exec "build/benchmark/Distortion_optimization/$name" "$@"

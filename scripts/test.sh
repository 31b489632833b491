#!/usr/bin/env bash
# Builds everything (library checks, tests, examples, benchmarks) in Release in build/ and runs
# the whole test suite. Works from any directory; the exit code is ctest's.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

bash scripts/install_dependencies.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release \
  -DBUILD_TESTING=ON -DBUILD_EXAMPLES=ON -DBUILD_BENCHMARKS=ON
cmake --build build -j2
ctest --test-dir build --output-on-failure

#!/usr/bin/env bash
# Builds the tests, the examples and the tool in Release in build/, the manual with Doxygen
# (build/doc/html), and runs the whole test suite. Works from any directory; the exit code is
# ctest's (or the build's, or Doxygen's on a warning). The benchmarks are built by
# scripts/bench.sh.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

bash scripts/install_dependencies.sh
bash scripts/configure.sh build \
  -DBUILD_TESTING=ON -DBUILD_EXAMPLES=ON -DBUILD_BENCHMARKS=OFF
cmake --build build -j2
# The manual and reference (Doxygen, into build/doc/html): a warning is an error (Doxyfile).
(cd doc/Distortion_optimization && doxygen Doxyfile)
# Two at a time: the GoogleTest tests one after the other (they share a lock), the installed-package
# build, the examples and the demo beside them.
ctest --test-dir build --output-on-failure -j2

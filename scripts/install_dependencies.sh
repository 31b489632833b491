#!/usr/bin/env bash
# Installs the Debian 12 packages needed to build, test and benchmark Distortion_optimization.
# Idempotent: does nothing when every package is already installed.
set -euo pipefail

PACKAGES=(
  build-essential cmake ninja-build ccache
  libcgal-dev libeigen3-dev libboost-dev libtbb-dev libgmp-dev libmpfr-dev
  libtet1.5-dev libgtest-dev libbenchmark-dev
  libsuitesparse-dev libmetis-dev libopenblas-dev  # CHOLMOD, its METIS ordering and BLAS: triangle maps' Newton systems
  doxygen       # the manual, built by scripts/test.sh (any warning fails it)
  libcgal-demo  # ships /usr/share/doc/libcgal-dev/data.tar.gz (real meshes); no Qt without recommends
)

if ! command -v dpkg >/dev/null 2>&1; then
  echo "install_dependencies: dpkg not found (not Debian?); install manually: ${PACKAGES[*]}" >&2
  exit 0
fi

missing=()
for pkg in "${PACKAGES[@]}"; do
  if ! dpkg -s "$pkg" 2>/dev/null | grep -q '^Status: install ok installed'; then
    missing+=("$pkg")
  fi
done

if [ "${#missing[@]}" -eq 0 ]; then
  echo "install_dependencies: all ${#PACKAGES[@]} Debian packages already installed, nothing to do."
  exit 0
fi

SUDO=()
if [ "$(id -u)" -ne 0 ]; then
  if command -v sudo >/dev/null 2>&1; then
    SUDO=(sudo)
  else
    echo "install_dependencies: missing ${missing[*]}; run as root (sudo not available)." >&2
    exit 1
  fi
fi

echo "install_dependencies: installing missing Debian packages: ${missing[*]}"
"${SUDO[@]}" apt-get update
"${SUDO[@]}" env DEBIAN_FRONTEND=noninteractive \
  apt-get install -y --no-install-recommends "${PACKAGES[@]}"

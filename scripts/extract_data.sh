#!/usr/bin/env bash
# Usage: extract_data.sh DIR
# Copies a few real meshes shipped by Debian's libcgal-demo / libcgal-dev into DIR (flattened:
# DIR/mushroom.off, ..., DIR/sphere.mesh). Files already present are kept. A missing tarball is
# reported on stderr but is not an error: the C++ side skips or fails with its own message.
set -euo pipefail

if [ "$#" -ne 1 ]; then
  echo "usage: $0 DIR" >&2
  exit 2
fi
DIR=$1
DOC_DIR=${CGAL_DOC_DIR:-/usr/share/doc/libcgal-dev}

mkdir -p "$DIR"
DIR=$(cd "$DIR" && pwd)

TMP=$(mktemp -d "$DIR/.extract.XXXXXX")
trap 'rm -rf "$TMP"' EXIT

status=0

# extract TARBALL MEMBER...: extract the members not yet in DIR, then move them flat into DIR.
extract() {
  local tarball=$1; shift
  local wanted=() member
  for member in "$@"; do
    [ -s "$DIR/$(basename "$member")" ] || wanted+=("$member")
  done
  [ "${#wanted[@]}" -eq 0 ] && return 0
  if [ ! -r "$tarball" ]; then
    echo "extract_data: $tarball not found (install libcgal-demo); missing: ${wanted[*]}" >&2
    status=1
    return 0
  fi
  if ! tar -xzf "$tarball" -C "$TMP" "${wanted[@]}"; then
    echo "extract_data: could not extract all of ${wanted[*]} from $tarball" >&2
    status=1
  fi
  for member in "${wanted[@]}"; do
    if [ -s "$TMP/$member" ]; then
      mv -f "$TMP/$member" "$DIR/$(basename "$member")"
    fi
  done
}

extract "$DOC_DIR/data.tar.gz" \
  data/meshes/mushroom.off \
  data/meshes/lion-head.off \
  data/meshes/mannequin-devil.off \
  data/meshes/nefertiti.off \
  data/meshes/three_peaks.off \
  data/meshes/bunny00.off \
  data/meshes/holes.off \
  data/meshes/lion.off \
  data/meshes/blobby.off \
  data/meshes/helmet.off \
  data/meshes/hand.off \
  data/meshes/dino.off \
  data/meshes/pig.stl \
  data/meshes/eight.off \
  data/meshes/elephant.off \
  data/meshes/elephant-with-holes.off \
  data/meshes/knot1.off \
  data/meshes/sphere.off \
  data/meshes/sphere.ply \
  data/meshes/sphere.stl

extract "$DOC_DIR/examples.tar.gz" \
  examples/Tetrahedral_remeshing/data/sphere.mesh

if [ "$status" -eq 0 ]; then
  echo "extract_data: meshes ready in $DIR"
fi
exit 0

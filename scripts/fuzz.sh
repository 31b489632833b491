#!/usr/bin/env bash
# Fuzzes the OFF, OBJ, Medit and TetGen readers, the PLY, STL and GOCAD paths (the package's checks
# of the bytes, then CGAL's readers), the vertex-list, vertex-weight and vertex-pair readers (the
# tool's --fix, --vertex-weights and --seams files) and the tool's command-line parser with libFuzzer
# (clang), AddressSanitizer and UBSan.
#   bash scripts/fuzz.sh [seconds per target, default 600] [target ...]
# Seeds: the real meshes extracted by the build (build/data) and small hand-written files.
# Exits non-zero if a reader crashed, hung or raised a sanitizer report; artifacts go to
# build/fuzz/<reader>/.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
seconds="${1:-600}"
shift || true
targets=("$@")
[ "${#targets[@]}" -gt 0 ] || targets=(read_OFF read_OBJ read_MEDIT_soup read_TetGen_pair read_PLY read_STL read_GOCAD read_vertex_list command_line)

missing=()
for pkg in clang libclang-rt-14-dev libeigen3-dev libcgal-dev libboost-dev libgmp-dev libmpfr-dev libcgal-demo; do
  dpkg -s "$pkg" 2>/dev/null | grep -q '^Status: install ok installed' || missing+=("$pkg")
done
if [ "${#missing[@]}" -gt 0 ]; then
  SUDO=(); [ "$(id -u)" -ne 0 ] && SUDO=(sudo)
  "${SUDO[@]}" apt-get update
  "${SUDO[@]}" env DEBIAN_FRONTEND=noninteractive apt-get install -y --no-install-recommends "${missing[@]}"
fi

out=build/fuzz
mkdir -p "$out"
bash scripts/extract_data.sh build/data >/dev/null

status=0
for reader in "${targets[@]}"; do
  dir="$out/$reader"
  mkdir -p "$dir/corpus" "$dir/artifacts"
  case "$reader" in
    read_OFF)
      cp build/data/*.off "$dir/corpus/" 2>/dev/null || true
      printf 'OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n' > "$dir/corpus/triangle.off"
      # The hostile cases of issues 19 and 20: BOM, NUL, escapes, subnormals, extra face, huge counts.
      printf '\xef\xbb\xbfOFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n' > "$dir/corpus/bom.off"
      printf 'OFF\n3 1 0\n0 0 0\n1 0\0009 0\n0 1 0\n3 0 1 2\n' > "$dir/corpus/nul.off"
      printf 'OFF\n3 1 0\n0 0 0\n1e-320 0 0\n0 1 0\n3 0 1 2\n' > "$dir/corpus/subnormal.off"
      printf 'OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n3 0 2 1\n' > "$dir/corpus/extra_face.off"
      printf 'OFF\n16777216 16777216 0\n\x1b[31m\n' > "$dir/corpus/huge_counts.off" ;;
    read_OBJ)
      printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1/1 2/1 3/1\nf -1 -2 -3\n' > "$dir/corpus/triangle.obj"
      printf '# comment\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3\nf 1 3 4\n' > "$dir/corpus/square.obj"
      printf '\xef\xbb\xbfv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1//1 2//1 3//1\n' > "$dir/corpus/bom.obj" ;;
    read_MEDIT_soup)
      cp build/data/*.mesh "$dir/corpus/" 2>/dev/null || true
      printf 'MeshVersionFormatted 1\nDimension 3\nVertices\n4\n0 0 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 0\nTetrahedra\n1\n1 2 3 4 1\nEnd\n' > "$dir/corpus/tet.mesh" ;;
    read_TetGen_pair)   # .node text, a NUL byte, .ele text
      { printf '4 3 0 1\n1 0 0 0 1\n2 1 0 0 1\n3 0 1 0 1\n4 0 0 1 1\n'; printf '\0'; printf '1 4 1\n1 1 2 3 4 7\n'; } \
        > "$dir/corpus/tet.tetgen"
      { printf '# 0-based, quadratic\n4 3 1 0\n0 0 0 0 5\n1 1 0 0 5\n2 0 1 0 5\n3 0 0 1 5\n'; printf '\0'
        printf '1 10 0\n0 0 1 2 3 0 1 2 3 0 1\n'; } > "$dir/corpus/quadratic.tetgen" ;;
    read_PLY)
      cp build/data/*.ply "$dir/corpus/" 2>/dev/null || true
      printf 'ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n' > "$dir/corpus/triangle.ply"
      { printf 'ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\nelement face 1\nproperty list uchar uint vertex_indices\nend_header\n'
        printf '\0\0\0\0\0\0\0\0\0\0\0\0\0\0\200\077\0\0\0\0\0\0\0\0\0\0\0\0\0\0\200\077\0\0\0\0'
        printf '\003\0\0\0\0\001\0\0\0\002\0\0\0'; } > "$dir/corpus/triangle_binary.ply" ;;
    read_STL)
      cp build/data/*.stl "$dir/corpus/" 2>/dev/null || true
      printf 'solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nendloop\nendfacet\nendsolid t\n' > "$dir/corpus/triangle.stl" ;;
    read_GOCAD)
      printf 'GOCAD TSurf 1\nHEADER {\nname: t\n}\nTFACE\nVRTX 1 0 0 0\nVRTX 2 1 0 0\nVRTX 3 0 1 0\nTRGL 1 2 3\nEND\n' > "$dir/corpus/triangle.ts" ;;
    read_vertex_list)
      printf '# pinned\n0\n12\n\n999\n' > "$dir/corpus/list.txt"
      printf '\xef\xbb\xbf3 # bom\n-1\n1000\n7 8\n' > "$dir/corpus/bad.txt"
      printf '# seams\n0 1\n8 7\n\n998 999 # last\n' > "$dir/corpus/seams.txt" ;;
    command_line)
      printf -- '--source\0s.off\0--target\0t.off\0--output\0o.off\0--measure\0conformal*isometric\0--threads\0-5' > "$dir/corpus/args"
      printf -- '--source\0a.mesh\0--output\0./a.mesh\0--report\0r.json\0--untangle\0--fix\0none\0--iterations\0-1' > "$dir/corpus/args2" ;;
  esac
  source_file=test/Distortion_optimization/fuzz/fuzz_reader.cpp
  case "$reader" in
    read_vertex_list) source_file=test/Distortion_optimization/fuzz/fuzz_vertex_list.cpp ;;
    command_line) source_file="tools/distortion_optimizer/test/fuzz_command_line.cpp tools/distortion_optimizer/command_line.cpp" ;;
  esac
  echo "fuzz.sh: building $reader"
  clang++ -std=c++17 -g -O1 -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=undefined \
    -DFUZZ_READER="$reader" -Iinclude -I/usr/include/eigen3 \
    $source_file -o "$dir/fuzz_$reader"
  echo "fuzz.sh: running $reader for $seconds s"
  # The command-line target stat()s the paths it makes up: run it where they name nothing of ours.
  if ! (cd "$dir" && "./fuzz_$reader" -max_total_time="$seconds" -max_len=16384 -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 \
       -artifact_prefix=artifacts/ corpus > log.txt 2>&1); then
    echo "fuzz.sh: $reader FAILED, see $dir/log.txt and $dir/artifacts/"
    status=1
  fi
  grep -E "stat::number_of_executed_units|stat::peak_rss_mb|Done [0-9]+ runs" "$dir/log.txt" | sed "s/^/fuzz.sh: $reader: /" || true
done
exit "$status"

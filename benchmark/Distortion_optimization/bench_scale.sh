#!/usr/bin/env bash
# How a triangle map's optimization grows with the mesh (issue 64): lion-head (libcgal-demo, a
# disk of 16.7K triangles) and its linear subdivisions (each triangle into four: 67K, 267K, 1.07M
# triangles), parametrized by the tool as a user runs it: Tutte's start, symmetric Dirichlet, the
# border fixed and then free (global injectivity kept), on one thread and on two. For each run the
# table gives the wall time (reading and writing included), the optimization's own seconds and
# iterations (from the report), seconds per iteration, the final energy and the peak resident
# memory; last, for each case and thread count, the exponent of seconds per iteration against
# triangles, fitted by least squares on the logarithms (1 is linear).
#
#   bash benchmark/Distortion_optimization/bench_scale.sh [levels [threads...]]
#   (default: levels 0 to 3, threads 1 2; run after scripts/test.sh)
source "$(dirname "${BASH_SOURCE[0]}")/tool_common.sh"
LEVELS=${1:-3}
[[ $LEVELS =~ ^[0-9]+$ ]] || { echo "levels: a number of subdivisions (0 to 3 fit in 2 GB)" >&2; exit 2; }
shift || true
THREADS=("$@")
[ ${#THREADS[@]} -gt 0 ] || THREADS=(1 2)
LION=$ROOT/build/data/lion-head.off
[ -f "$LION" ] || { echo "no $LION (the build copies it from libcgal-demo)" >&2; exit 1; }
command -v /usr/bin/time > /dev/null || { echo "GNU time (/usr/bin/time, Debian package time) measures the memory" >&2; exit 1; }

# The subdivisions, written by the tool (a run of 0 iterations, --subdivide N --subdivided-source).
cp "$LION" "$OUT/lion0.off"
for ((level = 1; level <= LEVELS; ++level)); do
  "$TOOL" --source "$LION" --output "$OUT/scratch.obj" --iterations 0 --subdivide "$level" \
    --subdivided-source "$OUT/lion$level.off" --quiet > /dev/null
done

printf '%-6s %-6s %9s %7s %9s %11s %6s %10s %13s %8s\n' border threads triangles wall_s optimize_s s_per_iter iters "" final_E RSS_MB
declare -A fit
for border in fixed free; do
  fix=()
  [ "$border" = free ] && fix=(--fix none)
  for threads in "${THREADS[@]}"; do
    for ((level = 0; level <= LEVELS; ++level)); do
      report=$OUT/report.json
      /usr/bin/time -f '%e %M' -o "$OUT/time.txt" "$TOOL" --source "$OUT/lion$level.off" --output "$OUT/out.obj" \
        --measure symmetric_dirichlet "${fix[@]}" --threads "$threads" --quiet --report "$report" > /dev/null
      read -r wall rss < "$OUT/time.txt"
      cells=$(field "$report" cells)
      seconds=$(field "$report" seconds)
      sweeps=$(field "$report" sweeps)
      per=$(awk -v s="$seconds" -v k="$sweeps" 'BEGIN { print (k > 0 ? s / k : 0) }')
      printf '%-6s %-6s %9d %7.2f %9.2f %11.4f %6d %10s %13.8g %8.0f\n' "$border" "$threads" "$cells" "$wall" "$seconds" \
        "$per" "$sweeps" "" "$(field "$report" final_energy)" "$(awk -v k="$rss" 'BEGIN { print k / 1024 }')"
      fit[$border,$threads]+="$cells $per
"
    done
  done
done

echo
for key in "${!fit[@]}"; do
  printf 'exponent of seconds per iteration, border %s, %s thread(s): %s\n' "${key%,*}" "${key#*,}" \
    "$(printf '%s' "${fit[$key]}" | awk 'NF == 2 && $2 > 0 { x = log($1); y = log($2); n++; sx += x; sy += y; sxx += x * x; sxy += x * y }
      END { if(n < 2) print "n/a (one size)"; else printf "%.2f", (n * sxy - sx * sy) / (n * sxx - sx * sx) }')"
done | sort

#!/usr/bin/env bash
# Measure a Release build from an empty build folder: the compiler CPU (sum
# over compiler calls of user + sys, logged by scripts/compile_cpu_log.sh as
# the compiler launcher), the number of calls, the wall time, the load
# average before and after (other work on the machine stretches the wall
# time, hardly the CPU) and the heaviest files. docs/performance.md, "Build
# time", quotes its figures.
#
#   bash scripts/measure_build.sh railstab [FOLDER]   the quick start's build
#                                                     (bash scripts/build.sh railstab)
#   bash scripts/measure_build.sh all [FOLDER]        every target, as
#                                                     bash scripts/build.sh does
#
# FOLDER (default build-measure) is deleted first. The per-call log stays in
# FOLDER/compile_cpu.log ("file cpu_seconds" a line).
set -euo pipefail
cd "$(dirname "$0")/.."
what=${1:?railstab or all}
dir=${2:-build-measure}
case "$what" in
  railstab) options=(-DRAILSTAB_BUILD_TESTS=OFF -DRAILSTAB_BUILD_BENCHMARKS=OFF -DRAILSTAB_BUILD_EXAMPLES=OFF)
            target=(--target railstab) ;;
  all) options=(-DRAILSTAB_BUILD_TESTS=ON -DRAILSTAB_BUILD_BENCHMARKS=ON -DRAILSTAB_BUILD_EXAMPLES=ON)
       target=() ;;
  *) echo "measure_build.sh: expected railstab or all, got '$what'" >&2; exit 2 ;;
esac
rm -rf "$dir"
log=$(realpath -m "$dir/compile_cpu.log")
load_before=$(cut -d' ' -f1-3 /proc/loadavg)
start=$(date +%s.%N)
cmake -S . -B "$dir" -DCMAKE_BUILD_TYPE=Release "${options[@]}" \
  -DCMAKE_CXX_COMPILER_LAUNCHER="$PWD/scripts/compile_cpu_log.sh" >/dev/null
RAILSTAB_COMPILE_LOG=$log cmake --build "$dir" -j2 "${target[@]}" > "$dir/build_output.txt"
end=$(date +%s.%N)
echo "build of '$what' in $dir: $(awk -v s="$start" -v e="$end" 'BEGIN {printf "%.0f", e - s}') s wall" \
     "(configure included), load average before $load_before, after $(cut -d' ' -f1-3 /proc/loadavg)"
awk '{s += $2} END {printf "compiler CPU: %.1f s over %d calls\n", s, NR}' "$log"
echo "heaviest files (CPU s):"
sort -k2 -n -r "$log" | head -8 | sed "s|$PWD/||"

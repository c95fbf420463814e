#!/usr/bin/env bash
# Compiler launcher that measures what each compiler call costs: runs the
# command it is given and appends "<source file> <CPU seconds>" (user + sys
# of the call and its children, GNU time) to the file named by
# RAILSTAB_COMPILE_LOG. Used to measure the build (docs/performance.md,
# "Build time"); the sum over a build's calls is its compiler CPU, which does
# not depend on what else the machine runs, unlike the wall time.
#
#   cmake -S . -B build-timed -DCMAKE_CXX_COMPILER_LAUNCHER=$PWD/scripts/compile_cpu_log.sh
#   RAILSTAB_COMPILE_LOG=/tmp/cpu.log cmake --build build-timed -j2 --target railstab
#   awk '{s += $2} END {print NR " calls, " s " s"}' /tmp/cpu.log
#   sort -k2 -n -r /tmp/cpu.log | head     # the heaviest files
set -u
log=${RAILSTAB_COMPILE_LOG:-/dev/null}
src=?
prev=
for a in "$@"; do              # the source file is the argument after -c
  [ "$prev" = "-c" ] && src=$a
  prev=$a
done
t=$(mktemp)
/usr/bin/time -f '%U %S' -o "$t" "$@"
rc=$?
read -r u s < <(tail -n 1 "$t")   # a failed call adds a line before
rm -f "$t"
echo "$src $(awk -v u="$u" -v s="$s" 'BEGIN {printf "%.2f", u + s}')" >> "$log"
exit $rc

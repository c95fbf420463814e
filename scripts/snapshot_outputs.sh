#!/usr/bin/env bash
# Numbers of every shipped case, for a before/after comparison of a change
# that must not change results (a refactor): runs critical-speed, eigen,
# equilibrium, simulate (short) and, for profile contacts, contact-geometry
# on every cases/*.toml with the given executable, and keeps the
# machine-readable outputs (JSON, CSV) with the lines that carry a time or a
# version removed (they differ from run to run).
#
#   bash scripts/snapshot_outputs.sh RAILSTAB OUT_DIR
#   diff -r OUT_BEFORE OUT_AFTER        # empty: bit-identical numbers
#
# Environment: CASES (default cases/*.toml).
set -uo pipefail
cd "$(dirname "$0")/.."
railstab=$(realpath "$1")
out=$(realpath -m "$2")
mkdir -p "$out"
cases=${CASES:-$(ls cases/*.toml)}

# Lines that legitimately change between runs: timings, version, host.
volatile='seconds|_s_cpu|cpu_s|wall|real_time|run_time|"version"|railstab_version|elapsed|date|host'

run() {  # name, command...
  local name=$1; shift
  local dir=$out/$name
  mkdir -p "$dir"
  "$railstab" "$@" --out "$dir/files" > "$dir/stdout.txt" 2> "$dir/stderr.txt"
  echo "exit $?" > "$dir/exit.txt"
  if [ -d "$dir/files" ]; then
    find "$dir/files" -type f \( -name '*.json' -o -name '*.csv' \) | sort | while read -r f; do
      grep -Ev "$volatile" "$f" | sed "s|$out|OUT|g" > "$dir/$(basename "$f")"
    done
    rm -rf "$dir/files"
  fi
  # stdout/stderr: progress and timings vary; keep the lines without them.
  for s in stdout stderr; do
    grep -Ev "$volatile|[0-9.]+ s( |$|\))|CPU|ms\b" "$dir/$s.txt" | sed "s|$out|OUT|g" > "$dir/$s.kept" || true
    rm "$dir/$s.txt"
  done
}

for scene in $cases; do
  base=$(basename "$scene" .toml)
  echo "== $base" >&2
  if grep -q "^\[bodies\|^\[\[bodies\|^\[train" "$scene"; then
    run "$base.critical_speed" critical-speed "$scene" --no-plots
    run "$base.eigen" eigen "$scene" --speed 40
    run "$base.equilibrium" equilibrium "$scene" --speed 40
    run "$base.simulate" simulate "$scene" --speed 40 --t-end 0.3 --no-error-estimate --no-plots
  fi
  if grep -q 'geometry = "profiles"' "$scene"; then
    run "$base.contact_geometry" contact-geometry "$scene" --no-plots
  fi
done

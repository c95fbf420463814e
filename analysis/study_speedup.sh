#!/usr/bin/env bash
# Parallel speed-up of `railstab study` (README "Parameter studies"): 100
# critical-speed searches of the thesis vehicle (10 cone angles x 10
# secondary lateral dampings of the front bogie, 5-150 m/s, grid 2.5 m/s),
# once with --jobs 1 and once with --jobs 2; wall and CPU time of each
# (GNU time), the speed-up wall(1)/wall(2), and a check that both runs wrote
# the same CSV.
#   usage: bash analysis/study_speedup.sh [RAILSTAB] [JOBS_MAX]
set -euo pipefail
cd "$(dirname "$0")/.."
railstab=${1:-./build/railstab}
jobs_max=${2:-2}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
study=(study cases/thesis_vehicle_tangent.toml
       --vary contacts.thesis_knife_edge.cone_angle_rad=0.05:0.14:0.01
       --vary 'elements.secondary_bogie1.damping_N_s_per_m[1]=1e4:5.5e4:5e3'
       --from 5 --to 150 --step 2.5 --no-plots)
echo "load before: $(cut -d' ' -f1-3 /proc/loadavg) on $(nproc) cores"
declare -A wall
for j in 1 $(seq 2 "$jobs_max"); do
  /usr/bin/time -f "%e %U %S" -o "$work/time_$j" "$railstab" "${study[@]}" --jobs "$j" \
      --out "$work/jobs_$j" > "$work/log_$j" 2> "$work/err_$j"
  read -r w u s < "$work/time_$j"
  wall[$j]=$w
  echo "jobs $j: wall $w s, CPU $(echo "$u + $s" | bc) s (user $u, sys $s); $(grep -c '' "$work/jobs_$j/thesis_vehicle_tangent_study.csv") CSV lines"
  head -3 "$work/log_$j" | sed 's/^/  /'
done
for j in $(seq 2 "$jobs_max"); do
  cmp "$work/jobs_1/thesis_vehicle_tangent_study.csv" "$work/jobs_$j/thesis_vehicle_tangent_study.csv"
  echo "speed-up jobs $j / jobs 1: $(echo "scale=2; ${wall[1]} / ${wall[$j]}" | bc) (CSV identical)"
done
echo "load after: $(cut -d' ' -f1-3 /proc/loadavg)"

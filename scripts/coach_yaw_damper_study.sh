#!/usr/bin/env bash
# Passenger coach (cases/coach_tangent.toml): critical speed against the
# series stiffness of its yaw dampers (README, "Passenger coach: critical speed
# against yaw-damper series stiffness").
#
# For every series stiffness k_s a temporary copy of the scene is made with
# series_stiffness_N_per_m = k_s (written before --set and `railstab study`
# existed; `railstab study --vary elements.<name>.series_stiffness_N_per_m=...`
# now does the finite values without copies), and two limits besides: "plain" (the yaw dampers as line_spring_damper with the
# same force-velocity table: k_s = infinity) and "none" (the yaw dampers
# removed). `railstab critical-speed` runs on each; the critical speed, the
# hunting frequency and the mode go into plots/coach_yaw_damper_study.csv,
# the plot into plots/coach_yaw_damper_study.png.
#
# Usage: bash scripts/coach_yaw_damper_study.sh   (after scripts/build.sh)
# Environment: RAILSTAB (default ./build/railstab), FROM / TO / STEP speed
# grid in m/s (default 20 / 300 / 5: 300 m/s is the CLI's speed limit).
set -euo pipefail
cd "$(dirname "$0")/.."
railstab=${RAILSTAB:-./build/railstab}
from=${FROM:-20}
to=${TO:-300}
step=${STEP:-5}
scene=cases/coach_tangent.toml
stiffnesses_MN_per_m="1 2 3 5 6 8 10 20 30 50 100 1000 10000"

[ -x "$railstab" ] || { echo "$railstab not found: build first (bash scripts/build.sh)" >&2; exit 1; }
command -v gnuplot >/dev/null || { echo "gnuplot not found" >&2; exit 1; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# The [[elements]] tables of type series_spring_damper removed (a table runs
# from its [header] line to the next one).
drop_series_dampers() {
  awk '
    function flush() { if (buf != "" && !drop) printf "%s", buf; buf = ""; drop = 0 }
    /^\[/ { flush() }
    { buf = buf $0 "\n"; if ($0 ~ /^type = "series_spring_damper"/) drop = 1 }
    END { flush() }' "$1"
}

# One critical-speed run: variant label, series stiffness (N/m, or "inf" /
# "none"), scene copy. Appends a CSV row and a gnuplot data row.
csv=$work/study.csv
dat=$work/study.dat
echo "variant,series_stiffness_N_per_m,critical_speed_m_per_s,hunting_frequency_Hz,hunting_mode,stable_up_to_m_per_s,run_time_s" > "$csv"
run() {
  local label=$1 k=$2 file=$3
  local t0 t1 json v f mode stable_to=""
  t0=$(date +%s.%N)
  "$railstab" critical-speed "$file" --out "$work/out_$label" --from "$from" --to "$to" \
    --step "$step" --no-plots > "$work/log_$label.txt" 2>&1 || {
    echo "critical-speed failed for $label:" >&2; cat "$work/log_$label.txt" >&2; exit 1; }
  t1=$(date +%s.%N)
  json=$(ls "$work/out_$label"/*_critical_speed.json)
  if grep -q '"unstable_at_start": true' "$json"; then
    echo "$label: already unstable at $from m/s: lower FROM" >&2; exit 1
  fi
  if grep -q '^  "critical_speed_m_per_s": [0-9]' "$json"; then
    v=$(sed -n 's/^  "critical_speed_m_per_s": \(.*\),$/\1/p' "$json")
    f=$(sed -n 's/^  "hunting_frequency_Hz": \(.*\),$/\1/p' "$json")
    mode=$(sed -n 's/^  "hunting_mode": "\(.*\)",$/\1/p' "$json")
  else
    v=""; f=""; mode=""; stable_to=$to
  fi
  local dt
  dt=$(echo "$t1 - $t0" | bc -l)
  printf '%s,%s,%s,%s,%s,%s,%.2f\n' "$label" "$k" "$v" "$f" "$mode" "$stable_to" "$dt" >> "$csv"
  echo "$label: k_s = $k N/m: ${v:-stable up to $to} m/s${f:+ at $f Hz, $mode} ($(printf %.2f "$dt") s)" >&2
}

start=$(date +%s.%N)
for k_MN in $stiffnesses_MN_per_m; do
  k=$(echo "$k_MN * 1000000" | bc)
  copy=$work/coach_ks_${k_MN}MN.toml
  sed -e "s/^series_stiffness_N_per_m = .*/series_stiffness_N_per_m = $k.0/" \
      -e "s/^name = \"coach_tangent\"/name = \"coach_ks_${k_MN}MN\"/" "$scene" > "$copy"
  grep -q "^series_stiffness_N_per_m = $k.0" "$copy" || { echo "sed did not set k_s in $copy" >&2; exit 1; }
  run "ks_${k_MN}MN" "$k" "$copy"
done
# k_s -> infinity: a plain damper with the same table.
sed -e 's/^type = "series_spring_damper"/type = "line_spring_damper"/' \
    -e '/^series_stiffness_N_per_m = /d' \
    -e 's/^name = "coach_tangent"/name = "coach_plain_damper"/' "$scene" > "$work/plain.toml"
run plain_damper inf "$work/plain.toml"
drop_series_dampers "$scene" | sed 's/^name = "coach_tangent"/name = "coach_no_yaw_damper"/' \
  > "$work/none.toml"
grep -q series_spring_damper "$work/none.toml" && { echo "yaw dampers not removed" >&2; exit 1; }
run no_yaw_damper none "$work/none.toml"
total=$(echo "$(date +%s.%N) - $start" | bc -l)

# gnuplot data: k in MN/m, V_crit (NaN when stable in range), frequency,
# the lower bound (the top of the range) where stable.
awk -F, -v top="$to" 'NR > 1 && $2 != "inf" && $2 != "none" {
  v = ($3 == "") ? "NaN" : $3; f = ($4 == "") ? "NaN" : $4; s = ($3 == "") ? top : "NaN"
  print $2 / 1e6, v, f, s }' "$csv" > "$dat"
plain=$(awk -F, '$1 == "plain_damper" { print ($3 == "" ? "NaN" : $3) }' "$csv")
none=$(awk -F, '$1 == "no_yaw_damper" { print ($3 == "" ? "NaN" : $3) }' "$csv")
cat > "$work/study.gp" <<EOF
set terminal pngcairo size 900,560
set output 'study.png'
set logscale x
set xrange [0.7:15000]
set yrange [0:$to + 20]
set y2range [0:12]
set xlabel 'yaw-damper series stiffness k_s (MN/m)'
set ylabel 'critical speed (m/s)'
set y2label 'hunting frequency (Hz)'
set ytics nomirror
set y2tics
set grid
set key bottom right
set title 'coach\_tangent: 4 yaw dampers, c = 450 kN s/m (slope at 0 of the blow-off table)'
plot 'study.dat' using 1:2 with linespoints pt 7 lw 2 title 'critical speed', \
     'study.dat' using 1:4 with points pt 9 ps 1.8 title 'stable up to the top of the range', \
     'study.dat' using 1:3 axes x1y2 with linespoints pt 6 dt 2 title 'hunting frequency', \
     $plain with lines lt 3 lw 2 title 'plain damper (k_s = inf): $(printf %.1f "$plain") m/s', \
     $none with lines lt 4 lw 2 title 'no yaw dampers: $(printf %.1f "$none") m/s'
EOF
(cd "$work" && gnuplot study.gp)
[ -s "$work/study.png" ] || { echo "gnuplot wrote no plot" >&2; exit 1; }
mkdir -p plots
cp "$csv" plots/coach_yaw_damper_study.csv
cp "$work/study.png" plots/coach_yaw_damper_study.png
printf 'study of %s critical-speed runs in %.1f s (wall)\n' \
  "$(($(wc -l < "$csv") - 1))" "$total" >&2
echo "wrote plots/coach_yaw_damper_study.csv plots/coach_yaw_damper_study.png"

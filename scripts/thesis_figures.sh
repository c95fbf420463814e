#!/usr/bin/env bash
# Thesis chapter-5 time-domain scenarios (figures 5.11-5.21), one command:
# the bogie and the complete vehicle on tangent track and through the
# clothoid into the R = 1000 m arc, at 20 and 40 m/s. Writes CSVs, run JSONs
# (integrator, error estimate, run time) and PNGs into out/figures and copies
# the PNGs shown in the README into plots/.
set -euo pipefail
cd "$(dirname "$0")/.."
out=out/figures
for scene in thesis_bogie_tangent thesis_bogie_curve thesis_vehicle_tangent thesis_vehicle_curve; do
  for v in 20 40; do
    echo "== $scene at $v m/s" >&2
    ./build/railstab simulate "cases/$scene.toml" --speed $v --out $out
  done
done
mkdir -p plots
for f in thesis_bogie_tangent_20mps_wheelset_lateral thesis_bogie_tangent_40mps_wheelset_lateral \
         thesis_bogie_tangent_20mps_wheelset_yaw thesis_bogie_tangent_40mps_body_yaw \
         thesis_bogie_curve_20mps_wheelset_lateral thesis_bogie_curve_20mps_wheelset_absolute_roll \
         thesis_bogie_curve_20mps_body_absolute_roll \
         thesis_bogie_curve_40mps_wheelset_lateral thesis_vehicle_tangent_40mps_wheelset_lateral \
         thesis_vehicle_curve_20mps_wheelset_lateral thesis_vehicle_curve_20mps_wheelset_absolute_roll \
         thesis_vehicle_curve_20mps_body_absolute_roll thesis_vehicle_curve_20mps_body_roll thesis_vehicle_curve_40mps_wheelset_lateral; do
  cp "$out/$f.png" plots/
done

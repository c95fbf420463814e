#!/usr/bin/env bash
# Thesis chapter-5 time-domain scenarios (figures 5.11-5.21), one command:
# writes CSVs and PNGs into out/figures and copies the PNGs shown in the
# README into plots/.
set -euo pipefail
cd "$(dirname "$0")/.."
out=out/figures
./build/railstab simulate cases/thesis_bogie_tangent.toml --speed 20 --out $out
./build/railstab simulate cases/thesis_bogie_tangent.toml --speed 40 --out $out
./build/railstab simulate cases/thesis_bogie_curve.toml --out $out
./build/railstab simulate cases/thesis_vehicle_tangent.toml --speed 20 --out $out
./build/railstab simulate cases/thesis_vehicle_tangent.toml --speed 40 --out $out
./build/railstab simulate cases/thesis_vehicle_curve.toml --out $out
mkdir -p plots
for f in thesis_bogie_tangent_20mps_wheelset_lateral thesis_bogie_tangent_40mps_wheelset_lateral \
         thesis_bogie_tangent_20mps_wheelset_yaw thesis_bogie_curve_20mps_wheelset_lateral \
         thesis_bogie_curve_20mps_absolute_roll thesis_vehicle_tangent_40mps_wheelset_lateral \
         thesis_vehicle_curve_20mps_wheelset_lateral thesis_vehicle_curve_20mps_absolute_roll \
         thesis_vehicle_curve_20mps_roll; do
  cp "$out/$f.png" plots/
done

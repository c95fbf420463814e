#!/usr/bin/env bash
# Error against run time of every integrator on the thesis vehicle (tangent,
# 20 m/s, 20 s, the case's 1 mm initial offset): the study behind the default
# integrator. About 2 minutes. Writes out/work_precision/ and copies the plot
# and table shown in the README into plots/.
set -euo pipefail
cd "$(dirname "$0")/.."
out=out/work_precision
./build/railstab work-precision cases/thesis_vehicle_tangent.toml --speed 20 --t-end 20 \
  --budget 8 --out $out \
  --integrators cvode_bdf,cvode_bdf_q2,cvode_adams,arkode_erk,arkode_dirk,arkode_dirk_q3,arkode_imex \
  --rtols 1e-2,3e-3,1e-3,3e-4,1e-4,1e-5,1e-6
mkdir -p plots
# (the files carry the speed; the README shows them under the old names)
cp $out/thesis_vehicle_tangent_20mps_work_precision.png plots/thesis_vehicle_tangent_work_precision.png
cp $out/thesis_vehicle_tangent_20mps_work_precision.md plots/thesis_vehicle_tangent_work_precision.md

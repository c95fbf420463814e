#!/usr/bin/env bash
# The README's bifurcation diagram of the thesis bogie on S1002/UIC60: the
# branch of flange-hunting orbits from the cycle a time-domain run settles on
# at 41 m/s, through its fold (the nonlinear critical speed, 34.78 m/s) and
# down the unstable orbits to 0.5 mm. About 15 min CPU (60 orbits, 6-42 s
# each; docs/performance.md). Writes out/s1002_bifurcation and copies the PNG
# into plots/.
set -euo pipefail
cd "$(dirname "$0")/.."
out=out/s1002_bifurcation
./build/railstab bifurcation cases/thesis_bogie_s1002_tangent.toml --from 20 --to 50 \
  --max-amplitude 0.008 --cycle-speed 41 --no-hopf-branch --max-orbits 60 --out "$out"
mkdir -p plots
cp "$out/thesis_bogie_s1002_tangent_bifurcation_diagram.png" plots/

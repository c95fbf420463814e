#!/usr/bin/env bash
# The bifurcation diagrams of docs/nonlinear.md on S1002/UIC60, copied into
# plots/ (the data in out/s1002_bifurcation_<which>):
#   bogie   (the default) the thesis bogie's branch of flange-hunting orbits
#           from the cycle a run settles on at 41 m/s, through its fold (the
#           nonlinear critical speed, 34.99 m/s) and down the unstable
#           orbits; about 3.5 min CPU (17 orbits; docs/performance.md);
#   vehicle the thesis vehicle's branch from its flange-hunting cycle at
#           100 m/s down through its fold (75.89 m/s) and up the unstable
#           orbits to the Hopf point (118.5 m/s); about 18 min CPU (69
#           orbits).
set -euo pipefail
cd "$(dirname "$0")/.."
which=${1:-bogie}
out=out/s1002_bifurcation_$which
case "$which" in
  bogie)
    ./build/railstab bifurcation cases/thesis_bogie_s1002_tangent.toml --from 20 --to 50 \
      --max-amplitude 0.008 --cycle-speed 41 --no-hopf-branch --max-orbits 60 --out "$out"
    stem=thesis_bogie_s1002_tangent ;;
  vehicle)
    ./build/railstab bifurcation cases/thesis_vehicle_s1002_tangent.toml --from 60 --to 150 \
      --max-amplitude 0.008 --cycle-speed 100 --no-hopf-branch --max-orbits 150 --out "$out"
    stem=thesis_vehicle_s1002_tangent ;;
  *) echo "usage: $0 [bogie|vehicle]" >&2; exit 2 ;;
esac
mkdir -p plots
cp "$out/${stem}_bifurcation_diagram.png" plots/

#!/usr/bin/env bash
# Quick-start command 1: install packages, build, run the main job: the
# critical-speed report of the thesis vehicle on tangent track and in the
# R = 1000 m canted arc (Markdown reports, JSON and plots in out/). Builds
# only the executable: the tests, benchmarks and examples are for
# scripts/test.sh.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install_deps.sh
bash scripts/build.sh railstab
./build/railstab critical-speed cases/thesis_vehicle_tangent.toml --out out
./build/railstab critical-speed cases/thesis_vehicle_curve.toml --arc-length 2000 --out out
echo "reports: out/thesis_vehicle_tangent_critical_speed.md out/thesis_vehicle_curve_arc2000m_critical_speed.md"

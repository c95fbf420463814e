#!/usr/bin/env bash
# Quick-start command 1: install packages, build, run the main job.
# Until the critical-speed job exists the main job is the thesis bogie on
# tangent track at 20 and 40 m/s (1 mm initial offset), with plots in out/.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install_deps.sh
bash scripts/build.sh
./build/railstab simulate cases/thesis_bogie_tangent.toml --speed 20 --out out
./build/railstab simulate cases/thesis_bogie_tangent.toml --speed 40 --out out

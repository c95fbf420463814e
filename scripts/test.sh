#!/usr/bin/env bash
# Quick-start command 2: build and run every test; in CI also the whole
# suite under ASan + UBSan and the fuzzers (scripts/sanitize.sh; locally:
# RAILSTAB_SANITIZE=1 bash scripts/test.sh).
set -euo pipefail
cd "$(dirname "$0")/.."
if [ "${CI:-}" = "true" ] || [ "${RAILSTAB_SANITIZE:-}" = "1" ]; then
  bash scripts/install_deps.sh ci
else
  bash scripts/install_deps.sh test
fi
bash scripts/build.sh
(cd build && ctest --output-on-failure -j2)
if [ "${CI:-}" = "true" ] || [ "${RAILSTAB_SANITIZE:-}" = "1" ]; then
  bash scripts/sanitize.sh
fi

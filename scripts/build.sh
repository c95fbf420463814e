#!/usr/bin/env bash
# Configure and build railstab (Release) into ./build.
#
#   bash scripts/build.sh            everything: the executable, the tests,
#                                    the benchmarks and the examples
#   bash scripts/build.sh railstab   only the executable (the quick start)
set -euo pipefail
cd "$(dirname "$0")/.."
if [ "${1:-}" = "railstab" ]; then
  # Options off only in a fresh build folder: a folder configured for the
  # tests keeps them (the quick start after the tests must not drop them).
  extra=()
  [ -f build/CMakeCache.txt ] || extra=(-DRAILSTAB_BUILD_TESTS=OFF -DRAILSTAB_BUILD_BENCHMARKS=OFF
                                        -DRAILSTAB_BUILD_EXAMPLES=OFF)
  cmake -S . -B build -DCMAKE_BUILD_TYPE=Release "${extra[@]}" >/dev/null
  cmake --build build -j2 --target railstab
else
  cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DRAILSTAB_BUILD_TESTS=ON \
    -DRAILSTAB_BUILD_BENCHMARKS=ON -DRAILSTAB_BUILD_EXAMPLES=ON >/dev/null
  cmake --build build -j2
fi

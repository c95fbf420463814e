#!/usr/bin/env bash
# Install the Debian packages railstab needs (idempotent: does nothing when
# they are all present). Run as root on Debian 12.
#
#   bash scripts/install_deps.sh          what the `railstab` executable needs
#                                         (compiler, numeric libraries, gnuplot)
#   bash scripts/install_deps.sh test     also the test suite's: GoogleTest,
#                                         GNU parallel (the sharded-study test),
#                                         and the Python module's build (python3-dev,
#                                         pybind11-dev, numpy) and tests (pytest;
#                                         scipy and matplotlib for the examples)
#   bash scripts/install_deps.sh ci       also CI's sanitizer stage: clang and
#                                         its sanitizer runtime
set -euo pipefail
packages=(g++ cmake make libeigen3-dev libarpack2-dev libsundials-dev libsuitesparse-dev gnuplot-nox
          libtomlplusplus-dev libcli11-dev)
# The Python module (python/; built wherever these are installed) and its
# tests and examples. pandas is optional (study(dataframe=True)).
python=(python3-dev pybind11-dev python3-numpy python3-pytest python3-scipy python3-matplotlib)
case "${1:-}" in
  "") ;;
  test) packages+=(libgtest-dev parallel "${python[@]}") ;;
  ci) packages+=(libgtest-dev parallel "${python[@]}" clang libclang-rt-14-dev) ;;
  *) echo "install_deps.sh: unknown set '$1' (expected nothing, 'test' or 'ci')" >&2; exit 2 ;;
esac
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "installing: ${missing[*]}" >&2
  apt-get update -qq
  DEBIAN_FRONTEND=noninteractive apt-get install -y -qq "${missing[@]}" >/dev/null
fi

#!/usr/bin/env bash
# Install the Debian packages railstab needs (idempotent: does nothing when
# they are all present). Run as root on Debian 12.
set -euo pipefail
packages=(g++ cmake make libeigen3-dev libarpack2-dev libsundials-dev libsuitesparse-dev gnuplot-nox
          libtomlplusplus-dev libcli11-dev libgtest-dev clang libclang-rt-14-dev
          parallel)  # GNU parallel: the sharded-study example (README "Parameter studies")
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "installing: ${missing[*]}" >&2
  apt-get update -qq
  DEBIAN_FRONTEND=noninteractive apt-get install -y -qq "${missing[@]}" >/dev/null
fi

#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Copyright (C) the ctid authors
# Installs what is missing (Debian packages), then configures and builds
# everything into build/. Sourced by scripts/run-demo and scripts/run-tests.
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BUILD="${CTID_BUILD_DIR:-$ROOT/build}"

# Debian 12 packages the build, the tests and the demos need.
# fonts-freefont-otf and ghostscript: Octave's headless PNG printing needs
# both and a --no-install-recommends install of octave brings neither.
# libnlopt-dev: the bounded optimiser of the Qn maximum-likelihood search.
PACKAGES=(g++ cmake make pkg-config octave liboctave-dev octave-control
          libeigen3-dev libgtest-dev libbenchmark-dev libnlopt-dev
          fonts-freefont-otf ghostscript)

missing=()
for package in "${PACKAGES[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$package" 2>/dev/null |
       grep -q "install ok installed"; then
    missing+=("$package")
  fi
done
# Figures are printed through gnuplot (headless); any gnuplot variant does.
if ! command -v gnuplot >/dev/null 2>&1; then
  missing+=(gnuplot-nox)
fi

if ((${#missing[@]})); then
  echo "Installing missing packages: ${missing[*]}"
  SUDO=""
  if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq \
    --no-install-recommends "${missing[@]}"
fi

cmake -S "$ROOT" -B "$BUILD" -DCMAKE_BUILD_TYPE=Release
cmake --build "$BUILD" -j"$(nproc)"

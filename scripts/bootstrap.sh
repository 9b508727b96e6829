#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Copyright (C) the ctid authors
# Sourced by scripts/run-demo and scripts/run-tests: installs the Debian
# packages that are missing and defines the two builds into build/ (or
# $CTID_BUILD_DIR):
#
#   ctid_bootstrap demo   the MEX gateways only (tests and benchmarks off):
#                         what the demos need, the first result in minutes
#   ctid_bootstrap all    everything: gateways, core tests, benchmarks
#
# Both compile with one job per core ($(nproc), or $CTID_JOBS) and through
# ccache (installed with the rest), so that a second run recompiles
# nothing and the package test's `pkg install` finds the gateways compiled.
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BUILD="${CTID_BUILD_DIR:-$ROOT/build}"
# (nproc without the OpenMP variables, which it would otherwise obey)
JOBS="${CTID_JOBS:-$(env -u OMP_NUM_THREADS -u OMP_THREAD_LIMIT nproc)}"

# Debian 12 packages the gateways and the demos need.
# fonts-freefont-otf and ghostscript: Octave's headless PNG printing needs
# both and a --no-install-recommends install of octave brings neither.
# libnlopt-dev: the bounded optimiser of the Qn maximum-likelihood search.
# ccache: a rebuild, and the Octave package's `pkg install` in the tests
# (tests/packaging), reuse the gateways already compiled.
DEMO_PACKAGES=(g++ cmake make pkg-config octave liboctave-dev octave-control
               libeigen3-dev libnlopt-dev fonts-freefont-otf ghostscript
               ccache)
# ... and the test suite and benchmarks in addition.
TEST_PACKAGES=(libgtest-dev libbenchmark-dev)

ctid_install_missing() {
  local missing=() package
  for package in "$@"; do
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
    local SUDO=""
    if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
    $SUDO apt-get update -qq
    DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq \
      --no-install-recommends "${missing[@]}"
  fi
}

ctid_launcher() {
  if command -v ccache >/dev/null 2>&1; then
    echo -DCMAKE_CXX_COMPILER_LAUNCHER=ccache
  fi
}

ctid_bootstrap() {
  local mode=$1
  case $mode in
    demo)
      ctid_install_missing "${DEMO_PACKAGES[@]}"
      cmake -S "$ROOT" -B "$BUILD" -DCMAKE_BUILD_TYPE=Release \
            -DCTID_BUILD_TESTS=OFF -DCTID_BUILD_BENCH=OFF $(ctid_launcher)
      cmake --build "$BUILD" --target octave_mex -j"$JOBS"
      ;;
    all)
      ctid_install_missing "${DEMO_PACKAGES[@]}" "${TEST_PACKAGES[@]}"
      cmake -S "$ROOT" -B "$BUILD" -DCMAKE_BUILD_TYPE=Release \
            -DCTID_BUILD_TESTS=ON -DCTID_BUILD_BENCH=ON $(ctid_launcher)
      cmake --build "$BUILD" -j"$JOBS"
      ;;
    *)
      echo "ctid_bootstrap: mode 'demo' or 'all', not '$mode'" >&2
      return 2
      ;;
  esac
}

#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Copyright (C) the ctid authors
# The Octave package from a clean tree: scripts/dist builds the tarball,
# `pkg install -local` installs it into a fresh temporary prefix (HOME, the
# package prefix and the local package list all in a temporary folder, so
# the user's own packages are never touched), and a second Octave session
# runs check_installed_package.m (pkg load ctid, CONTSID calls, inline
# tests). Removes everything it made.
#
#   test_octave_package.sh <source dir> [octave executable]
set -euo pipefail
src=$(cd "$1" && pwd)
octave=${2:-octave-cli}
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
mkdir -p "$tmp/home"

tarball=$("$src/scripts/dist" "$tmp/dist" 2> "$tmp/dist.log" | tail -n 1)
if [[ ! -f $tarball ]]; then
  cat "$tmp/dist.log" >&2
  echo "FAIL: scripts/dist made no tarball" >&2
  exit 1
fi
echo "built $(basename "$tarball")"

# The gateways compile at install time; ccache (when present) keeps a
# repeated run short.
if command -v ccache > /dev/null; then
  export CXX="ccache ${CXX:-g++}"
  # (the cache of the real HOME: Octave runs with a temporary one)
  export CCACHE_DIR=${CCACHE_DIR:-$(ccache -k cache_dir 2> /dev/null ||
                                    echo "$HOME/.ccache")}
fi

setup="pkg ('prefix', '$tmp/pkg', '$tmp/pkg'); pkg ('local_list', '$tmp/octave_packages');"
# One compiler at a time (pkg runs make --jobs nproc ("overridable")).
HOME=$tmp/home OMP_NUM_THREADS=1 "$octave" --no-gui --no-window-system -q --eval "
  $setup
  pkg ('install', '-local', '$tarball');
  assert (numel (pkg ('list', 'ctid')), 1);
  printf ('installed into %s\n', pkg ('list', 'ctid'){1}.dir);"

HOME=$tmp/home "$octave" --no-gui --no-window-system -q --eval "
  $setup
  addpath ('$here');
  check_installed_package ('$tmp/pkg', '$src');"
echo "test_octave_package: passed"

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

# The gateways compile at install time (a real `pkg install`: the
# package's src/Makefile runs mkoctfile on every gateway). With ccache the
# compilations of the tree's own build (mex/CMakeLists.txt, configured with
# -DCMAKE_CXX_COMPILER_LAUNCHER=ccache, as scripts/run-tests does) are
# found in the cache: the Makefile compiles with the same command, and pkg
# unpacks the tarball under TMPDIR, which is the ccache base directory here
# (paths below it are hashed relative to it).
if command -v ccache > /dev/null; then
  export CXX="ccache $(mkoctfile -p CXX)"
  # (the cache of the real HOME: Octave runs with a temporary one)
  export CCACHE_DIR=${CCACHE_DIR:-$(ccache -k cache_dir 2> /dev/null ||
                                    echo "$HOME/.ccache")}
  mkdir -p "$tmp/unpack"
  export TMPDIR=$tmp/unpack CCACHE_BASEDIR=$tmp/unpack
  export CCACHE_STATSLOG=$tmp/ccache-stats.log
fi

setup="pkg ('prefix', '$tmp/pkg', '$tmp/pkg'); pkg ('local_list', '$tmp/octave_packages');"
start=$SECONDS
HOME=$tmp/home "$octave" --no-gui --no-window-system --no-history -q --eval "
  $setup
  pkg ('install', '-local', '$tarball');
  assert (numel (pkg ('list', 'ctid')), 1);
  printf ('installed into %s\n', pkg ('list', 'ctid'){1}.dir);"
echo "pkg install: $((SECONDS - start)) s"
if command -v ccache > /dev/null; then
  # (the compilations of this install: cache hits and misses)
  ccache --show-log-stats 2> /dev/null | grep -E -i "hits|misses" || true
  unset TMPDIR CCACHE_BASEDIR CCACHE_STATSLOG
fi

HOME=$tmp/home "$octave" --no-gui --no-window-system --no-history -q --eval "
  $setup
  addpath ('$here');
  check_installed_package ('$tmp/pkg', '$src');"
echo "test_octave_package: passed"

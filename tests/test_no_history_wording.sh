#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Copyright (C) the ctid authors

# No development history in the product: code, comments, help texts,
# tests, scripts and documents say what the code does and why, not the
# episode that led to it. Fails, listing the offending lines, when a
# tracked text file (other than NEWS.md and this script) names an issue,
# session, round or stop by its number (the word, then a number), calls a
# simulator a "replica" or a check a "blind check", or
# when a tracked file's name does the same. A word followed by something
# other than a number ("a round-off", "round (x)", "the end stops (0 and
# 100 %)") is not history. Skips (exit 77, a visible SKIP) outside a git
# checkout, e.g. in an unpacked release tarball.
#
#   test_no_history_wording.sh [source dir]

set -uo pipefail
src=${1:-$(dirname "${BASH_SOURCE[0]}")/..}
if ! src=$(cd "$src" 2> /dev/null && pwd -P); then
  echo "test_no_history_wording: no such folder: ${1:-}" >&2
  exit 2
fi
if ! command -v git > /dev/null 2>&1; then
  echo "SKIP: git not found, the tracked files cannot be listed"
  exit 77
fi
top=$(git -C "$src" rev-parse --show-toplevel 2> /dev/null) || top=""
if [ -z "$top" ] || [ "$(cd "$top" && pwd -P)" != "$src" ]; then
  echo "SKIP: $src is not the top of a git checkout"
  exit 77
fi
cd "$src" || exit 2

self=tests/test_no_history_wording.sh
words='(^|[^[:alpha:]])(session|issue|stop|round)s?[ _-]?#?[0-9]+'
words="$words|replica|blind[ -]check"
names='(session|issue|stop|round)s?[ _-]?#?[0-9]+|replica|blind|held-?out'

lines=$(git grep -nIiE "$words" -- . ':(exclude)NEWS.md' \
          ":(exclude)$self")
status=$?
if [ "$status" -gt 1 ]; then
  echo "test_no_history_wording: git grep failed ($status)" >&2
  exit 2
fi
files=$(git ls-files | grep -iE "$names")

if [ -z "$lines" ] && [ -z "$files" ]; then
  echo "test_no_history_wording: no history wording in $(git ls-files |
        wc -l) tracked files"
  exit 0
fi
if [ -n "$lines" ]; then
  echo "Development history in tracked files (say what the code does and"
  echo "why instead; NEWS.md is the place for history):"
  printf '%s\n' "$lines"
fi
if [ -n "$files" ]; then
  echo "Tracked files named after development history (rename them after"
  echo "what they hold or check):"
  printf '%s\n' "$files"
fi
echo "test_no_history_wording: FAILED, $(printf '%s\n' "$lines" |
      grep -c .) line(s), $(printf '%s\n' "$files" | grep -c .) file name(s)"
exit 1

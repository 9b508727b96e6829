## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {} ctid_test_skip (@var{name}, @var{why})
## Prints the line by which CTest reports the script test @var{name} as
## skipped, with the reason @var{why} (the test's SKIP_REGULAR_EXPRESSION
## in tests/CMakeLists.txt matches "CTID_TEST_SKIPPED"). The test then
## returns without checking anything more.
## @end deftypefn

function ctid_test_skip (name, why)
  printf ("CTID_TEST_SKIPPED %s: %s\n", name, why);
endfunction

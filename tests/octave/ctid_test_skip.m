## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {} ctid_test_skip (@var{why})
## Ends the running script test as skipped, for the reason @var{why} (e.g.
## the measured records are absent): raises the error
## @code{ctid:testSkipped}, which @code{ctid_run_script_test} turns into
## the line "CTID_TEST_SKIPPED <name>: <why>"; CTest reports a test whose
## output has that line as skipped (SKIP_REGULAR_EXPRESSION in
## tests/CMakeLists.txt). Called outside that runner, it is an error with
## the reason.
## @end deftypefn

function ctid_test_skip (why)
  error ("ctid:testSkipped", "%s", why);
endfunction

## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## Runs the script test tests/octave/<name>.m with the toolbox on the path;
## the script signals failure by raising an error, and a skip (its
## prerequisites absent) by calling ctid_test_skip, reported here as
## "CTID_TEST_SKIPPED <name>: <reason>" (CTest's skip pattern).
function ctid_run_script_test (name)
  root = ctid_test_root ();
  addpath (fullfile (root, "octave"));
  addpath (fullfile (root, "tests", "octave"));
  try
    feval (name);
  catch err
    if (strcmp (err.identifier, "ctid:testSkipped"))
      printf ("CTID_TEST_SKIPPED %s: %s\n", name, err.message);
      return;
    endif
    rethrow (err);
  end_try_catch
  printf ("%s: passed\n", name);
endfunction

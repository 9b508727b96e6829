## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## Runs the script test tests/octave/<name>.m with the toolbox on the path;
## the script signals failure by raising an error.
function ctid_run_script_test (name)
  root = ctid_test_root ();
  addpath (fullfile (root, "octave"));
  addpath (fullfile (root, "tests", "octave"));
  feval (name);
  printf ("%s: passed\n", name);
endfunction

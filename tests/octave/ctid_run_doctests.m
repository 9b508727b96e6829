## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## Runs the %!test / %!assert / %!error blocks of one toolbox file and fails
## (non-zero exit through error) unless every block passes.
##
## ctid_run_doctests ("rlssvf.m") -- path relative to <root>/octave.
function ctid_run_doctests (file)
  root = ctid_test_root ();
  addpath (fullfile (root, "octave"));
  target = fullfile (root, "octave", file);
  [dir, ~] = fileparts (target);
  if (strcmp (fileparts (file), "private"))
    ## a private function's tests call it (and its neighbours) by name
    addpath (dir);
    cleanup = onCleanup (@() rmpath (dir));
  endif
  [n, nmax] = test (target, "quiet", stdout);
  printf ("%s: %d of %d tests passed\n", file, n, nmax);
  if (nmax == 0)
    error ("ctid_run_doctests: %s has no tests", file);
  endif
  if (n != nmax)
    error ("ctid_run_doctests: %d of %d tests failed in %s", nmax - n, nmax, file);
  endif
endfunction

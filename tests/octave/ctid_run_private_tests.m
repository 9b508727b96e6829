## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {} ctid_run_private_tests (@var{file})
## Runs the inline tests of @file{octave/private/@var{file}} (the CTest
## glob of inline tests covers @file{octave/*.m} only), with the private
## folder on the path for the duration of the run, and errors unless
## every test passes, so that a script test can call it:
## @example
## function test_contsid_init_method ()
##   ctid_run_private_tests ("contsid_init_method.m");
## endfunction
## @end example
## @end deftypefn

function ctid_run_private_tests (file)
  root = ctid_test_root ();
  private_dir = fullfile (root, "octave", "private");
  addpath (fullfile (root, "octave"));
  addpath (private_dir);
  cleanup = onCleanup (@() rmpath (private_dir));
  [n, nmax] = test (fullfile (private_dir, file), "quiet");
  if (nmax == 0 || n != nmax)
    error ("ctid_run_private_tests: %s: %d of %d tests passed", file, n,
           nmax);
  endif
  printf ("%s: %d of %d tests passed\n", file, n, nmax);
endfunction

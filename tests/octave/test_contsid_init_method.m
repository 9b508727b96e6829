## -*- texinfo -*-
## @deftypefn {} {} test_contsid_init_method ()
## Runs the inline tests of @file{octave/private/contsid_init_method.m},
## the start-method reader of the refined-IV family (the CTest glob of
## inline tests covers @file{octave/*.m} only). Errors on a failure, so
## that CTest can run it:
## @example
## octave --no-gui -q --eval \
##   "addpath octave tests/octave; test_contsid_init_method"
## @end example
## The private folder is put on the path for the duration of the test.
## @end deftypefn

function test_contsid_init_method ()
  root = fileparts (fileparts (fileparts (mfilename ("fullpath"))));
  private_dir = fullfile (root, "octave", "private");
  addpath (fullfile (root, "octave"));
  addpath (private_dir);
  cleanup = onCleanup (@() rmpath (private_dir));
  [n, nmax] = test (fullfile (private_dir, "contsid_init_method.m"), "quiet");
  if (nmax == 0 || n != nmax)
    error ("test_contsid_init_method: %d of %d tests passed", n, nmax);
  endif
  printf ("test_contsid_init_method: %d of %d tests passed\n", n, nmax);
endfunction

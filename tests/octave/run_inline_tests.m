## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn  {} {} run_inline_tests ()
## @deftypefnx {} {} run_inline_tests (@var{files})
## Run the @code{%!} tests of the toolbox's Octave files and error if any
## fails, so that CTest can run them:
## @example
## octave --no-gui -q --eval "addpath octave tests/octave; run_inline_tests"
## @end example
## Without arguments, every @file{.m} file in @file{octave/} and in its
## class folders (@file{octave/@@*/}) is tested; @var{files} is a cell of
## paths relative to @file{octave/}, e.g. @code{@{"prbs.m",
## "@@iddata/iddata.m"@}}.  The log of a failing file is printed.
## @end deftypefn

function run_inline_tests (files)
  here = fullfile (fileparts (fileparts (fileparts (mfilename ("fullpath")))),
                   "octave");
  addpath (here);
  if (nargin < 1)
    files = [list_m_files(here, ""), list_class_files(here)];
  endif
  failed = {};
  for k = 1:numel (files)
    file = fullfile (here, files{k});
    log = [tempname(), ".log"];
    fid = fopen (log, "w");
    [npass, ntest] = test (file, "quiet", fid);
    fclose (fid);
    printf ("%-40s %3d of %3d passed\n", files{k}, npass, ntest);
    if (npass < ntest || ntest == 0)
      printf ("%s\n", fileread (log));
      failed{end+1} = files{k};
    endif
    delete (log);
  endfor
  if (! isempty (failed))
    error ("run_inline_tests:failed", "run_inline_tests: failures in %s",
           strjoin (failed, ", "));
  endif
endfunction

function files = list_m_files (root, sub)
  listing = dir (fullfile (root, sub, "*.m"));
  files = cellfun (@(name) fullfile (sub, name), {listing.name},
                   "uniformoutput", false);
endfunction

function files = list_class_files (root)
  files = {};
  classes = dir (fullfile (root, "@*"));
  for k = find ([classes.isdir])
    files = [files, list_m_files(root, classes(k).name)];
  endfor
endfunction

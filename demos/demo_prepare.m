## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{here} =} demo_prepare (@var{outdir})
## The prologue every demo shares: puts the toolbox (<repo>/octave) on the
## path, creates the output folder @var{outdir} when missing, and returns
## the demos folder.
## @end deftypefn

function here = demo_prepare (outdir)
  here = fileparts (mfilename ("fullpath"));
  addpath (fullfile (here, "..", "octave"));
  if (! exist (outdir, "dir"))
    mkdir (outdir);
  endif
endfunction

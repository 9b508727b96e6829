## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{tf} =} called_from_control (@var{name})
## True when the property @var{name} is read in the control package's
## convention: @var{name} is one on which MATLAB and the control package
## disagree, and the code that reached this class from outside is part of
## the control package.
##
## The control package and MATLAB disagree on @code{dat.y}: control's own
## functions (@code{arx}, @code{moen4}, ...) index it as a cell with one
## matrix per experiment, while MATLAB (and CONTSID scripts) get the matrix
## itself; likewise for @code{u} and @code{Domain}.  The first stack frame
## whose file is not in this @@iddata folder decides: a file installed
## under @file{packages/control-@var{version}/} gets the control behaviour,
## anything else (scripts, the command line, this toolbox) the MATLAB one.
## The frames of @code{contsid_guard}, which runs the public methods, are
## skipped as well.
## @end deftypefn

function tf = called_from_control (name)
  tf = false;
  if (! any (strcmp (name, {"OutputData", "InputData", "Domain"})))
    return;
  endif
  here = [fileparts(fileparts(mfilename ("fullpath"))), filesep()];
  frames = dbstack ("-completenames");
  for k = 2:numel (frames)
    file = frames(k).file;
    if (! strncmp (file, here, numel (here))
        && ! strcmp (frames(k).name, "contsid_guard"))
      tf = ! isempty (regexp (file, '[\\/]packages[\\/]control-[^\\/]+[\\/]',
                              "once"));
      return;
    endif
  endfor
endfunction

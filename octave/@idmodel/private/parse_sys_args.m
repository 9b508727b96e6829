## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {[@var{sys}, @var{styles}, @var{x}, @var{opt}] =} parse_sys_args (@var{fname}, @var{args})
## Reads the arguments of the plotting methods (bode, step, impulse,
## nyquist, pzmap): models (this toolbox's or the control package's),
## each optionally followed by a line style string; a numeric argument
## (frequencies or times; a cell @{wmin, wmax@} for bode); the options
## @code{'sd', k} (confidence band of k standard deviations) and
## @code{'fill'}.  Anything else: error @code{@var{fname}:badInput}.
## @end deftypefn

function [sys, styles, x, opt] = parse_sys_args (fname, args)
  sys = {};
  styles = {};
  x = [];
  opt = struct ("sd", 0, "fill", false);
  i = 1;
  while (i <= numel (args))
    a = args{i};
    if (isa (a, "idmodel") || isa (a, "lti"))
      sys{end+1} = a;
      styles{end+1} = "";
    elseif (ischar (a) && strcmpi (a, "sd"))
      if (i == numel (args) || ! isnumeric (args{i+1})
          || ! isscalar (args{i+1}) || ! (args{i+1} > 0))
        error ([fname ":badInput"], "%s: 'sd' needs a number > 0", fname);
      endif
      opt.sd = args{i+1};
      i++;
    elseif (ischar (a) && strcmpi (a, "fill"))
      opt.fill = true;
    elseif (ischar (a) && ! isempty (sys) && isempty (styles{end}))
      [~, valid] = __pltopt__ (fname, a, false);
      if (! valid)
        error ([fname ":badInput"], "%s: '%s' is not a line style", fname,
               a);
      endif
      styles{end} = a;
    elseif ((isnumeric (a) && isreal (a)) || iscell (a))
      if (iscell (a))
        if (numel (a) != 2 || ! all (cellfun ("isnumeric", a)))
          error ([fname ":badInput"], "%s: give {wmin, wmax}", fname);
        endif
        a = logspace (log10 (a{1}), log10 (a{2}), 200);
      endif
      if (isempty (a) || any (! isfinite (a(:))) || any (a(:) < 0))
        error ([fname ":badInput"],
               "%s: frequencies or times must be finite and >= 0", fname);
      endif
      if (any (a(:) > 1e100))
        ## Octave's plotting runs out of memory on such axes (and no model
        ## response means anything there).
        error ([fname ":badInput"],
               "%s: frequencies or times above 1e100 are not supported",
               fname);
      endif
      x = double (a(:));
    else
      error ([fname ":badInput"], "%s: unexpected argument %d (%s)",
             fname, i, class (a));
    endif
    i++;
  endwhile
  if (isempty (sys))
    error ([fname ":badInput"], "%s: no model given", fname);
  endif
endfunction

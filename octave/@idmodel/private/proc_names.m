## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {[@var{names}, @var{np}, @var{flags}] =} proc_names (@var{type})
## The parameters of the process model @var{type} (e.g. "P2DU", "P1D",
## "P3ZI"), in the SITB order Kp, Tp1, Tp2, Tp3, Tw, Zeta, Td, Tz, its
## number of poles and its letters (D delay, Z zero, U underdamped,
## I integrator).  A bad type: error @code{idproc:badInput}.
## @end deftypefn

function [names, np, flags] = proc_names (type)
  t = upper (type);
  if (! ischar (type) || isempty (regexp (t, '^P[0-3][DZUI]*$', "once")))
    error ("idproc:badInput",
           ["idproc: Type must be 'P' and 0-3 poles followed by any of ", ...
            "D, Z, U, I (e.g. 'P2DU'), got '%s'"], num2str (type));
  endif
  np = t(2) - "0";
  letters = t(3:end);
  if (numel (unique (double (letters))) != numel (letters))
    error ("idproc:badInput", "idproc: a letter repeated in Type '%s'", type);
  endif
  flags = struct ("D", any (letters == "D"), "Z", any (letters == "Z"),
                  "U", any (letters == "U"), "I", any (letters == "I"));
  if (flags.U && np < 2)
    error ("idproc:badInput",
           "idproc: 'U' (underdamped pair) needs 2 or 3 poles ('%s')", type);
  endif
  names = {"Kp"};
  if (flags.U)
    extra = {"Tp3"};
    names = [names, extra(1:np-2), {"Tw", "Zeta"}];
  else
    all_tp = {"Tp1", "Tp2", "Tp3"};
    names = [names, all_tp(1:np)];
  endif
  if (flags.D)
    names{end+1} = "Td";
  endif
  if (flags.Z)
    names{end+1} = "Tz";
  endif
endfunction

## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {[@var{G}, @var{delay}] =} lti_of (@var{P}, @var{form}, @var{fname})
## The control package's @code{tf} (@var{form} "tf") or @code{ss} ("ss")
## of the model struct @var{P} without its delays, and the ny-by-nu total
## delays (seconds, or samples in discrete time), which control 3.4 cannot
## hold.  The one place where models become control-package objects;
## loads the package (error @code{@var{fname}:notSupported} without it).
## @end deftypefn

function [G, delay] = lti_of (P, form, fname)
  need_control (fname);
  delay = repmat (P.InputDelay(:).', P.ny, 1);
  switch (P.kind)
    case {"idpoly", "idtf"}
      delay += P.par.IODelay;
    case "idproc"
      if (isfield (P.par.Structure, "Td"))
        delay += P.par.Structure.Td.Value;
      endif
  endswitch
  if (strcmp (P.kind, "idss"))
    p = P.par;
    finite_or_error ({p.A, p.B, p.C, p.D}, P.kind);
    G = feval ("ss", p.A, p.B, p.C, p.D, tsam (P));
    if (strcmp (form, "tf"))
      G = feval ("tf", G);
    endif
  else
    [num, den] = tf_parts (P);
    finite_or_error ([num(:); den(:)], P.kind);
    G = feval ("tf", num, den, tsam (P));
    if (strcmp (form, "ss"))
      G = feval ("ss", G);
    endif
  endif
endfunction

## The control package's pole and realisation routines do not return on
## NaN or Inf coefficients (the classes' set and setpvec refuse them; this
## is the last check before the conversion).
function finite_or_error (c, kind)
  if (! all (cellfun (@(x) all (isfinite (x(:))), c)))
    error ([kind ":badInput"], "%s: the model has NaN or Inf coefficients",
           kind);
  endif
endfunction

function t = tsam (P)
  t = P.Ts;
endfunction

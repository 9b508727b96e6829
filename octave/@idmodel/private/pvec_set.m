## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{P} =} pvec_set (@var{P}, @var{p})
## The model struct @var{P} with the parameters @var{p} (column, order of
## @code{pvec_of}, length already checked).
## @end deftypefn

function P = pvec_set (P, p)
  p = double (p(:));
  ## NaN or Inf coefficients would reach the control package's pole and
  ## realisation routines, which do not return on them; an idproc's NaN
  ## is a parameter not yet known, its own convention.
  if (any (isinf (p)) || (! strcmp (P.kind, "idproc") && any (isnan (p))))
    error ([P.kind ":badInput"],
           "%s: the parameters must be finite (NaN or Inf given)", P.kind);
  endif
  s = P.par;
  k = 0;
  switch (P.kind)
    case "idpoly"
      s.A(2:end) = take (numel (s.A) - 1);
      for j = 1:P.nu
        s.B{j}(:) = take (numel (s.B{j}));
      endfor
      s.C(2:end) = take (numel (s.C) - 1);
      s.D(2:end) = take (numel (s.D) - 1);
      for j = 1:P.nu
        s.F{j}(2:end) = take (numel (s.F{j}) - 1);
      endfor
    case "idtf"
      for i = 1:numel (s.Numerator)
        s.Numerator{i}(:) = take (numel (s.Numerator{i}));
      endfor
      for i = 1:numel (s.Denominator)
        s.Denominator{i}(2:end) = take (numel (s.Denominator{i}) - 1);
      endfor
      d = take (numel (s.IODelay));
      if (any (! isfinite (d)) || any (d < 0)
          || (P.Ts > 0 && any (d != round (d))))
        error ("idtf:badInput", ["idtf: the IODelay entries of the ", ...
               "parameter vector must be finite and >= 0 (whole samples ", ...
               "in discrete time)"]);
      endif
      s.IODelay(:) = d;
    case "idproc"
      names = proc_names (s.Type);
      for i = 1:numel (names)
        s.Structure.(names{i}).Value = take (1);
      endfor
    case "idss"
      for f = {"A", "B", "C", "D"}
        s.(f{1})(:) = take (numel (s.(f{1})));
      endfor
    case "idfrd"
      error ("idfrd:notSupported", "idfrd: frequency data have no parameters");
  endswitch
  P.par = s;

  function v = take (n)
    v = p(k+1:k+n);
    k += n;
  endfunction
endfunction


## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {[@var{p}, @var{names}] =} pvec_of (@var{M})
## The parameter vector of @var{M} in the SITB order (idpoly: A, B, C, D,
## F without the leading 1s; idtf: numerators, denominators without
## the leading 1, then the IODelay entries; idproc: Kp, Tp1, Tp2, Tp3, Tw, Zeta, Td, Tz of its type;
## idss: A, B, C, D column-wise) and the parameters' names.
## @end deftypefn

function [p, names] = pvec_of (M)
  s = M.par;
  p = [];
  names = {};
  switch (M.kind)
    case "idpoly"
      add ("a", s.A(2:end), "");
      for j = 1:M.nu
        add ("b", s.B{j}, suffix (j, M.nu));
      endfor
      add ("c", s.C(2:end), "");
      add ("d", s.D(2:end), "");
      for j = 1:M.nu
        add ("f", s.F{j}(2:end), suffix (j, M.nu));
      endfor
    case "idtf"
      for k = 1:numel (s.Numerator)
        add ("b", s.Numerator{k}, suffix (k, numel (s.Numerator)));
      endfor
      for k = 1:numel (s.Denominator)
        add ("f", s.Denominator{k}(2:end), suffix (k, numel (s.Numerator)));
      endfor
      ## the I/O delays are parameters of an idtf in the SITB (fixed
      ## unless estimated): nparams (idtf (1, [1 2])) is 3
      for k = 1:numel (s.IODelay)
        p(end+1, 1) = s.IODelay(k);
        names{end+1, 1} = sprintf ("iodelay%s", suffix (k, numel (s.IODelay)));
      endfor
    case "idproc"
      fn = proc_names (s.Type);
      for i = 1:numel (fn)
        p(end+1, 1) = s.Structure.(fn{i}).Value;
        names{end+1, 1} = fn{i};
      endfor
    case "idss"
      for f = {"A", "B", "C", "D"}
        X = s.(f{1});
        p = [p; X(:)];
        for i = 1:numel (X)
          [r, c] = ind2sub (size (X), i);
          names{end+1, 1} = sprintf ("%s(%d,%d)", f{1}, r, c);
        endfor
      endfor
    case "idfrd"
      p = zeros (0, 1);
  endswitch
  if (isempty (p))
    p = zeros (0, 1);
  endif

  function add (letter, c, suf)
    for i = 1:numel (c)
      p(end+1, 1) = c(i);
      names{end+1, 1} = sprintf ("%s%s%d", letter, suf, i);
    endfor
  endfunction
endfunction

function s = suffix (j, n)
  s = "";
  if (n > 1)
    s = sprintf ("%d_", j);
  endif
endfunction

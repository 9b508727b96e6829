## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {[@var{num}, @var{den}] =} tf_parts (@var{M})
## The ny-by-nu cells of numerators and denominators of the input-output
## part of @var{M} (descending powers of s, or of z in discrete time),
## without delays.  The one place where each class' parameters become a
## transfer function.
## @end deftypefn

function [num, den] = tf_parts (M)
  p = M.par;
  switch (M.kind)
    case "idpoly"
      num = cell (1, M.nu);
      den = cell (1, M.nu);
      for j = 1:M.nu
        b = p.B{j};
        a = conv (p.A, p.F{j});
        if (M.Ts > 0)              # q^-1 rows -> equal-length z rows
          n = max (numel (b), numel (a));
          b = [b, zeros(1, n - numel (b))];
          a = [a, zeros(1, n - numel (a))];
        endif
        num{j} = b;
        den{j} = a;
      endfor
    case "idtf"
      num = p.Numerator;
      den = p.Denominator;
    case "idproc"
      [num, den] = proc_tf (M);
    case "idss"
      [num, den] = ss_tf (p);
    case "idfrd"
      error ("idfrd:notSupported",
             "idfrd: frequency response data have no transfer function");
  endswitch
endfunction

function [num, den] = proc_tf (M)
  p = M.par;
  [names, np, flags] = proc_names (p.Type);
  v = struct ();
  for i = 1:numel (names)
    v.(names{i}) = p.Structure.(names{i}).Value;
    if (isnan (v.(names{i})))
      error ("idproc:badInput",
             "idproc: parameter %s of the %s model is not set (NaN)",
             names{i}, p.Type);
    endif
  endfor
  n = v.Kp;
  if (flags.Z)
    n = v.Kp * [v.Tz, 1];
  endif
  d = 1;
  if (flags.U)
    d = [v.Tw^2, 2 * v.Zeta * v.Tw, 1];
    if (np == 3)
      d = conv (d, [v.Tp3, 1]);
    endif
  else
    tp = {"Tp1", "Tp2", "Tp3"};
    for i = 1:np
      d = conv (d, [v.(tp{i}), 1]);
    endfor
  endif
  if (flags.I)
    d = [d, 0];
  endif
  first = find (d != 0, 1);
  d = d(first:end);
  g = d(1);
  num = {n / g};
  den = {d / g};
endfunction

## C (sI - A)^-1 B + D = (det (sI - A + B C) - det (sI - A)) / det (sI - A)
## + D, for each input-output pair.
function [num, den] = ss_tf (p)
  [ny, nu] = size (p.D);
  num = cell (ny, nu);
  den = cell (ny, nu);
  pa = poly (p.A);
  for i = 1:ny
    for j = 1:nu
      n = poly (p.A - p.B(:, j) * p.C(i, :)) - pa + p.D(i, j) * pa;
      first = find (abs (n) > 1e-14 * max (abs ([n, 1])), 1);
      if (isempty (first))
        n = 0;
      else
        n = n(first:end);
      endif
      num{i, j} = n;
      den{i, j} = pa;
    endfor
  endfor
endfunction

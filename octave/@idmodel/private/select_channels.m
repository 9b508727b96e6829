## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{Ms} =} select_channels (@var{M}, @var{P}, @var{subs})
## @code{M(i, j)}: the model from the inputs @var{j} to the outputs
## @var{i} (indices, logical masks or @qcode{":"}; @var{subs} as
## @code{subsref} receives them), with their delays, names and noise
## variance, as the System Identification Toolbox selects channels.  The
## whole model in its own order is @var{M} itself; a proper selection
## is built anew through the class constructor, without the parameter
## covariance of the estimate.  Errors: @code{<class>:badInput}.
## @end deftypefn

function Ms = select_channels (M, P, subs)
  kind = P.kind;
  if (numel (subs) != 2)
    error ([kind ":badInput"], "%s: select channels as M(outputs, inputs)",
           kind);
  endif
  try
    oi = (1:P.ny)(subs{1});
    ij = (1:P.nu)(subs{2});
  catch err
    error ([kind ":badInput"], "%s: M(i, j): %s", kind, err.message);
  end_try_catch
  oi = oi(:).';
  ij = ij(:).';
  if (isequal (oi, 1:P.ny) && isequal (ij, 1:P.nu))
    Ms = M;
    return;
  endif
  if (isempty (oi) || isempty (ij))
    error ([kind ":badInput"], "%s: M(i, j) selects no channel", kind);
  endif
  switch (kind)
    case "idtf"
      [num, den, iod] = get (M, "Numerator", "Denominator", "IODelay");
      Ms = idtf (num(oi, ij), den(oi, ij), P.Ts, "IODelay", iod(oi, ij));
    case "idpoly"
      [A, B, C, D, F] = get (M, "A", "B", "C", "D", "F");
      B = cellify (B);
      F = cellify (F);
      Ms = idpoly (A, B(ij), C, D, F(ij), 1, P.Ts);
    case "idss"
      [A, B, C, D, K, x0] = get (M, "A", "B", "C", "D", "K", "x0");
      Ms = idss (A, B(:, ij), C(oi, :), D(oi, ij), K(:, oi), x0, P.Ts);
    case "idfrd"
      [R, w] = get (M, "ResponseData", "Frequency");
      Ms = idfrd (R(oi, ij, :), w, "Ts", P.Ts);
    otherwise                          # idproc: one input, one output
      Ms = M;
      return;
  endswitch
  Ms = set (Ms, "InputDelay", P.InputDelay(ij), "InputName",
            P.InputName(ij), "InputUnit", P.InputUnit(ij), "OutputName",
            P.OutputName(oi), "OutputUnit", P.OutputUnit(oi),
            "NoiseVariance", P.NoiseVariance(oi, oi), "Name", P.Name);
endfunction

function c = cellify (x)
  c = x;
  if (! iscell (x))
    c = {x};
  endif
endfunction

## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{model} =} residtrace_base (@var{M}, @var{d})
## The @code{residtrace} model of @var{M} (a struct with B, F, nk as
## residtrace reads a model through contsid_model): one
## @qcode{"input"} channel per input with M's numerator and delay, M's
## denominator F, no output terms. Coefficients of F that are exactly zero
## are structural (integrators, a missing damping term) and stay fixed
## when the model is re-estimated.
## @end deftypefn

function model = residtrace_base (M, d)
  m = struct (M);
  B = m.B;
  if (! iscell (B))
    B = {B};
  endif
  chans = [];
  for j = 1:numel (B)
    b = B{j};
    first = find (b != 0, 1);
    if (isempty (first))
      b = 0;
    else
      b = b(first:end);
    endif
    c = residtrace_chan ("input", j, [], numel (b), m.nk(j),
                         sprintf ("u%d", j));
    c.B = b;
    chans = [chans; c];
  endfor
  F = m.F;
  model = struct ("F", F, "fixed", F(2:end) == 0, "channels", chans,
                  "out", struct ("type", {}, "c", {}, "cstd", {},
                                 "omega", {}),
                  "intersample", d.intersample, "Ts", d.Ts,
                  "effects", {{}}, "ltv", [], "noise", [],
                  "theta", [], "cov", [], "s2", NaN, "np", 0, "bic", NaN,
                  "e_est", [], "ok", true, "levels", false, "x0", false,
                  "phys", []);
endfunction

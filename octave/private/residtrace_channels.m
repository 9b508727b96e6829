## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{W} =} residtrace_channels (@var{chans}, @var{u}, @var{v}, @var{y})
## The signals that drive the channels of a @code{residtrace} model, one
## column per channel, from the inputs @var{u} (N-by-nu), a velocity
## @var{v} and an output @var{y} (N-by-1; used by @qcode{"signv"} and
## @qcode{"ypower"} channels only; default 0). Delays are not applied
## here. Channel types:
## @table @code
## @item input
## u(:, col); with a fraction f = param in (0, 1) (a transport delay
## that is not a whole number of samples: nk + f samples), the held input
## delayed by f of a sample, (1 - f) u(k) + f u(k-1) (the shifted hold
## replaced by the two held values with the same area and centre: exact
## at low frequency, the error of order (w Ts)^2)
## @item const
## 1 (an offset entering with the input)
## @item signv
## sign (v) (Coulomb friction, thesis eq. 4.17); v is the first column of
## @var{v} (the derivative of the output), or with param "y" its last
## column (the output read as a velocity)
## @item power
## u(:, col) .^ param (a polynomial input nonlinearity)
## @item clip
## u(:, col) clipped to +-param (with the input's own channel: a
## saturation or a dead zone)
## @item ypower
## y .^ param (a static nonlinearity of the output acting inside the
## dynamics, e.g. a hardening spring: Duffing's y^3); a fractional power
## keeps the sign, sign(y) |y|^param (sqrt: the outflow of a tank)
## @item node
## an inner node of the model clipped: z = F_a(0)/F_a(p) u(:, col) (unit
## static gain; param.Fa, param.Ts, param.rule) limited to [param.lo,
## param.hi] (a tank that overflows, a valve at its end stop); the model's
## F is then the part F_b after the node
## @end table
## Works row by row as well (a 1-by-nu @var{u} and a scalar @var{v});
## a fractional delay needs the previous sample, so a row is taken as it
## is. The signals are computed by the core (core/include/ctid/apps/
## residtrace/structure_fit.hpp, channel_signals, through
## @code{effect_sim_mex}); with @var{chans} alone, the channels are
## returned in the form that gateway takes.
## @end deftypefn

function W = residtrace_channels (chans, u, v, y)
  if (nargin == 1)
    W = encode (chans);
    return;
  endif
  if (nargin < 3)
    v = 0;
  endif
  if (nargin < 4)
    y = 0;
  endif
  N = rows (u);
  if (isscalar (v))
    v = repmat (v, N, 1);
  endif
  if (isscalar (y))
    y = repmat (y, N, 1);
  endif
  W = effect_sim_mex ("residtrace", "channels", u, v, y, encode (chans));
endfunction

## The channels as effect_sim_mex takes them (core/include/ctid/apps/
## residtrace/structure_fit.hpp, channel_signals), without their
## numerators.
function o = encode (chans)
  m = numel (chans);
  types = {"input", "const", "signv", "", "power", "clip", "ypower", "node"};
  o = struct ("kind", zeros (1, m), "col", zeros (1, m),
              "param", zeros (1, m), "nb", [chans.nb], "nk", [chans.nk],
              "node", {cell(1, m)});
  for j = 1:m
    c = chans(j);
    o.kind(j) = find (strcmp (types, c.type), 1) - 1;
    if (! isempty (c.col))
      o.col(j) = c.col;
    endif
    switch (c.type)
      case "signv"
        o.kind(j) += strcmp (c.param, "y");   # the output as a velocity
      case "node"
        P = c.param;
        o.node{j} = struct ("fa", P.Fa, "ts", P.Ts, "rule", lower (P.rule),
                            "lo", P.lo, "hi", P.hi);
      otherwise
        if (! isempty (c.param))
          o.param(j) = c.param;
        endif
    endswitch
  endfor
endfunction

%!test  # a fraction f of a sample: (1 - f) u(k) + f u(k-1), u(0) = u(1)
%! ch = residtrace_chan ("input", 1, 0.25, 1, 0, "u1");
%! u = [1; 3; -2; 5];
%! assert (residtrace_channels (ch, u, zeros (4, 1)), [1; 2.5; -0.75; 3.25],
%!         1e-15);
%! ch.param = [];                       # whole samples: the input itself
%! assert (residtrace_channels (ch, u, zeros (4, 1)), u);

%!test  # a transport delay of 3.4 samples on 1/(p + 1) with a held input:
%! ## the channel (nk = 3, f = 0.4) simulated as residtrace does, against
%! ## an exact simulation of the delayed held input in 50 sub-steps per
%! ## sample (an independent computation); the error is second order in
%! ## w Ts (here within 1 % of the output's RMS, steps held 10 samples),
%! ## whereas the delay rounded to 3 samples is several times further
%! ## off (about six)
%! randn ("state", 3); rand ("state", 3);
%! Ts = 0.05; N = 400; S = 50;
%! u = kron (sign (randn (40, 1)), ones (10, 1));
%! uf = kron (u, ones (S, 1));
%! d = round (3.4 * S);
%! uf = [zeros(d, 1); uf(1:end-d)];
%! a = exp (-Ts / S); x = 0; ye = zeros (N, 1); i = 0;
%! for k = 1:N
%!   ye(k) = x;
%!   for s = 1:S
%!     i++; x = a * x + (1 - a) * uf(i);
%!   endfor
%! endfor
%! ch = residtrace_chan ("input", 1, 0.4, 1, 3, "u1");
%! ch.B = 1;
%! m = struct ("F", [1 1], "fixed", false, "channels", ch,
%!             "out", struct ("type", {}, "c", {}, "cstd", {}, "omega", {}),
%!             "intersample", "zoh", "phys", []);
%! y = residtrace_simulate (m, u, Ts, [], 10);
%! r = sqrt (mean (ye .^ 2));
%! assert (sqrt (mean ((y - ye) .^ 2)) < 0.01 * r);
%! m.channels.param = 0;
%! y3 = residtrace_simulate (m, u, Ts, [], 10);
%! assert (sqrt (mean ((y3 - ye) .^ 2)) > 3 * sqrt (mean ((y - ye) .^ 2)));

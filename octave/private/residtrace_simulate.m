## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn  {} {[@var{y}, @var{x}, @var{uc}] =} residtrace_simulate (@var{model}, @var{u}, @var{Ts}, @var{loop}, @var{substeps})
## @deftypefnx {} {[@dots{}] =} residtrace_simulate (@dots{}, @var{thm})
## Simulated output of a @code{residtrace} model on the input @var{u}
## (N-by-nu), from rest. In closed loop the first input is replaced by
## r1 + C (r2 - y) (@var{loop}.r1 the external signal).
##
## The dynamic part is F(p) x = sum_j B_j(p) w_j(t - nk_j Ts) with the
## channel signals w_j of @code{residtrace_channels}; then y = x plus the
## output terms (offset, polynomial c2 x^2 + c3 x^3, sinusoid a sin(w t) +
## b cos(w t), t from the first sample).
##
## @itemize
## @item Open loop and no channel fed by the model's own velocity: the
## channels are computed from @var{u} and @code{simc} integrates the
## linear part exactly (ZOH or FOH as the data's InterSample).
## @item Coulomb friction (a @qcode{"signv"} channel), a nonlinearity of
## the output inside the dynamics (@qcode{"ypower"}: y^p of the model's
## own output, re-evaluated at each sub-step) or a closed loop
## (@var{loop} with fields @code{num}, @code{den} (controller C(q^-1)),
## @code{r1}, @code{r2}: u = r1 + C (r2 - y), y the simulated output):
## the model in observable canonical form is stepped through each
## sampling interval in @var{substeps} equal sub-steps, each exact (matrix
## exponential) for inputs held over the sub-step; sign(v) is re-evaluated
## at each sub-step from the simulated velocity v = dy/dt (or v = y for a
## first-order model: the output is then read as a velocity). The other
## inputs are held over the sampling interval (ZOH). This loop runs in
## the core (core/include/ctid/simulation/effect_simulator.hpp, gateway
## @code{effect_sim_mex}); in closed loop the channels of the controlled
## first input may be the input, a power or a clipped value of it
## (another kind is @code{residtrace:notSupported}).
## @end itemize
## With @var{thm} (N-by-np, the dynamic parameters at each sample as
## @code{residtrace_unpack} reads them) the model is time-varying: the
## sub-step of each sampling interval uses the parameters of its first
## sample (a single-input model in open loop goes to @code{simc}, which
## interpolates them linearly).
## An output saturation (@code{out} term @qcode{"sat"}, levels c = [lo
## hi]) clips the output last: y = min (max (x + terms, lo), hi).
## @var{x} is the dynamic part alone, @var{uc} the input applied (equal to
## @var{u} in open loop). A model with a physical realisation
## (@code{model.phys}: an end stop, a tank cascade) is simulated by
## @code{residtrace_physsim} (open loop only).
## @end deftypefn

function [y, x, uc] = residtrace_simulate (model, u, Ts, loop, substeps, thm)
  if (isfield (model, "phys") && ! isempty (model.phys))
    ## a physical realisation (an end stop, a tank cascade)
    if (! isempty (loop) || (nargin > 5 && ! isempty (thm)))
      error ("residtrace:notSupported",
             "residtrace: a physical realisation in closed loop or drifting");
    endif
    y = residtrace_physsim (model, u, Ts);
    x = y;
    uc = u;
    return;
  endif
  N = rows (u);
  chans = model.channels;
  if (nargin < 6)
    thm = [];
  endif
  if (! isempty (loop))
    u(:, 1) = loop.r1;        # the controlled input is r1 + C (r2 - y)
  endif
  needs_loop = (! isempty (loop) || any (strcmp ({chans.type}, "signv"))
                || any (strcmp ({chans.type}, "ypower")));
  if (! isempty (thm) && ! needs_loop && numel (chans) == 1
      && strcmp (chans.type, "input")
      && (isempty (chans.param) || chans.param == 0))
    n = numel (model.F) - 1;
    nb = chans.nb;
    T = repmat ([model.F(2:end), zeros(1, nb)], N, 1);
    free = find (! model.fixed);
    T(:, free) = thm(:, 1:numel (free));
    T(:, n+1:end) = thm(:, numel (free)+1:end);
    x = simc (T, [n nb chans.nk], u(:, chans.col), Ts,
              "InterSample", model.intersample);
    uc = u;
  elseif (! needs_loop && isempty (thm))
    W = residtrace_channels (chans, u, zeros (N, 1));
    B = {chans.B};
    x = simc (struct ("B", {B}, "F", model.F, "nk", [chans.nk]), W, Ts,
              "InterSample", model.intersample);
    uc = u;
  else
    [x, uc] = loop_sim (model, u, Ts, loop, substeps, thm);
  endif
  y = x + output_terms (model, x, Ts);
endfunction

function o = output_terms (model, x, Ts)
  o = zeros (size (x));
  sat = [];
  t = (0:numel (x) - 1)' * Ts;
  for k = 1:numel (model.out)
    m = model.out(k);
    switch (m.type)
      case "offset"
        o += m.c(1);
      case "poly"
        o += m.c(1) * x .^ 2 + m.c(2) * x .^ 3;
      case "sinusoid"
        o += m.c(1) * sin (m.omega * t) + m.c(2) * cos (m.omega * t);
      case "sat"
        sat = m.c;
    endswitch
  endfor
  if (! isempty (sat))
    y = x + o;
    o = min (max (y, sat(1)), sat(2)) - x;
  endif
endfunction

function [x, uc] = loop_sim (model, u, Ts, loop, substeps, thm)
  ## the core's effect-model simulator (core/include/ctid/
  ## effect_simulator.hpp) through effect_sim_mex
  N = rows (u);
  F = model.F;
  n = numel (F) - 1;
  chans = model.channels;
  m = numel (chans);
  closed = ! isempty (loop);
  types = {chans.type};
  kind = zeros (1, m);
  param = zeros (1, m);
  kind(strcmp (types, "signv")) = 1;
  for j = find (strcmp (types, "signv"))
    if (strcmp (chans(j).param, "y"))
      kind(j) = 2;
    endif
  endfor
  isy = strcmp (types, "ypower");
  kind(isy) = 3;
  param(isy) = [chans(isy).param];
  if (closed)
    ## the channels of the controlled first input are formed in the loop
    for j = find (kind == 0)
      if (isempty (chans(j).col) || chans(j).col != 1)
        continue;
      endif
      switch (types{j})
        case "input"
          if (! isempty (chans(j).param) && chans(j).param != 0)
            error ("residtrace:notSupported",
                   ["residtrace: a delay of a fraction of a sample on ", ...
                    "the controlled input"]);
          endif
          kind(j) = 4;
        case "power"
          kind(j) = 5; param(j) = chans(j).param;
        case "clip"
          kind(j) = 6; param(j) = chans(j).param;
        otherwise
          error ("residtrace:notSupported",
                 "residtrace: a '%s' channel of the controlled input",
                 types{j});
      endswitch
    endfor
  endif
  W = zeros (N, m);
  ex = (kind == 0);
  if (any (ex))
    W(:, ex) = residtrace_channels (chans(ex), u, zeros (N, 1));
  endif
  ## the simulator's states are those of a strictly proper model: a
  ## biproper channel (numerator of F's degree, a direct feedthrough)
  ## would put the input into the output that the sign of the velocity,
  ## the powers of the output or a controller read back
  if (any ([chans.nb] > n))
    error ("residtrace:notSupported",
           ["residtrace: a biproper model (direct feedthrough) with an ", ...
            "effect fed back from its output, a closed loop or drifting ", ...
            "parameters"]);
  endif
  b = zeros (n, m);
  for j = 1:m
    bj = chans(j).B(:);
    b(n-numel(bj)+1:n, j) = bj;
  endfor
  ## the output level the powers act on: x plus an output offset
  y_off = 0;
  poly = [0 0];
  for k = 1:numel (model.out)
    switch (model.out(k).type)
      case "offset"
        y_off += model.out(k).c(1);
      case "poly"
        poly = model.out(k).c(1:2);
    endswitch
  endfor
  o = struct ("ts", Ts, "f", F(2:end) / F(1), "b", b / F(1), "kind", kind,
              "nk", [chans.nk], "param", param, "y_off", y_off,
              "substeps", substeps);
  if (closed)
    o.controller_num = loop.num(:).';
    o.controller_den = loop.den(:).';
    o.r1 = loop.r1(:);
    o.r2 = loop.r2(:);
    o.poly = poly;
    t = (0:N-1)' * Ts;
    s = zeros (N, 1);
    for k = 1:numel (model.out)
      if (strcmp (model.out(k).type, "sinusoid"))
        c = model.out(k).c;
        s += c(1) * sin (model.out(k).omega * t) ...
             + c(2) * cos (model.out(k).omega * t);
      endif
    endfor
    o.s = s;
  endif
  if (! isempty (thm))
    free = find (! model.fixed);
    ft = repmat (F(2:end), N, 1);
    ft(:, free) = thm(:, 1:numel (free));
    bt = zeros (N, n * m);
    off = numel (free);
    for j = 1:m
      nb = chans(j).nb;
      bt(:, (j-1)*n + (n-nb+1:n)) = thm(:, off+1:off+nb);
      off += nb;
    endfor
    o.f_t = ft;
    o.b_t = bt;
  endif
  uc = u;
  if (closed)
    [x, uc(:, 1)] = effect_sim_mex ("residtrace", W, o);
  else
    x = effect_sim_mex ("residtrace", W, o);
  endif
endfunction

function o = out_at (model, x, t)
  o = 0;
  for k = 1:numel (model.out)
    m = model.out(k);
    switch (m.type)
      case "offset"
        o += m.c(1);
      case "poly"
        o += m.c(1) * x ^ 2 + m.c(2) * x ^ 3;
      case "sinusoid"
        o += m.c(1) * sin (m.omega * t) + m.c(2) * cos (m.omega * t);
    endswitch
  endfor
endfunction

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
## inputs are held over the sampling interval (ZOH).
## @end itemize
## With @var{thm} (N-by-np, the dynamic parameters at each sample as
## @code{residtrace_unpack} reads them) the model is time-varying: the
## sub-step of each sampling interval uses the parameters of its first
## sample (a single-input model in open loop goes to @code{simc}, which
## interpolates them linearly).
## An output saturation (@code{out} term @qcode{"sat"}, levels c = [lo
## hi]) clips the output last: y = min (max (x + terms, lo), hi).
## @var{x} is the dynamic part alone, @var{uc} the input applied (equal to
## @var{u} in open loop).
## @end deftypefn

function [y, x, uc] = residtrace_simulate (model, u, Ts, loop, substeps, thm)
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
      && strcmp (chans.type, "input"))
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
  N = rows (u);
  F = model.F;
  n = numel (F) - 1;
  chans = model.channels;
  m = numel (chans);
  ## Observable canonical form: x1 = y, x1' = -f1 x1 + x2 + b_(1) w, ...
  A = [-F(2:end)(:), eye(n, n-1)];
  Bc = zeros (n, m);
  for j = 1:m
    b = chans(j).B(:).';
    Bc(n-numel(b)+1:n, j) = b(:);
  endfor
  h = Ts / substeps;
  E = expm ([A, Bc; zeros(m, n + m)] * h);
  Phi = E(1:n, 1:n);
  Gam = E(1:n, n+1:end);
  isv = strcmp ({chans.type}, "signv");
  isy = strcmp ({chans.type}, "ypower");
  ypw = [chans(isy).param];
  yfrac = (ypw != fix (ypw));
  ## the output level the powers act on: x plus an output offset
  y_off = 0;
  for k = 1:numel (model.out)
    if (strcmp (model.out(k).type, "offset"))
      y_off += model.out(k).c(1);
    endif
  endfor
  vy = false (1, m);                        # Coulomb on the output itself
  for j = find (isv)
    vy(j) = strcmp (chans(j).param, "y");
  endfor
  isx = isv | isy;                          # fed by the model's own state
  velocity_is_y = (n == 1);
  nk = [chans.nk];
  closed = ! isempty (loop);
  uc = u;
  xs = zeros (n, 1);
  x = zeros (N, 1);
  if (closed)
    cn = loop.num(:).'; cd = loop.den(:).';
    ebuf = zeros (1, numel (cn));           # r2 - y at k, k-1, ..
    ubuf = zeros (1, numel (cd));           # controller output at k, k-1, ..
  endif
  uin = find (! isx);
  if (! closed)
    Wpre = residtrace_channels (chans, u, zeros (N, 1));
    for j = uin
      Wpre(:, j) = [zeros(nk(j), 1); Wpre(1:end-nk(j), j)];
    endfor
  endif
  for k = 1:N
    if (! isempty (thm))
      mk = residtrace_unpack (model, thm(k, :));
      A = [-mk.F(2:end)(:), eye(n, n-1)];
      for j = 1:m
        b = mk.channels(j).B(:).';
        Bc(:, j) = 0;
        Bc(n-numel(b)+1:n, j) = b(:);
      endfor
      E = expm ([A, Bc; zeros(m, n + m)] * h);
      Phi = E(1:n, 1:n);
      Gam = E(1:n, n+1:end);
    endif
    x(k) = xs(1);
    if (closed)
      yk = xs(1) + out_at (model, xs(1), (k - 1) * Ts);
      ebuf = [loop.r2(k) - yk, ebuf(1:end-1)];
      c = (cn * ebuf.' - cd(2:end) * ubuf(1:end-1).') / cd(1);
      ubuf = [c, ubuf(1:end-1)];
      uc(k, 1) = u(k, 1) + c;
    endif
    ## channel values at this sample (delayed ones from the history)
    if (closed)
      wk = zeros (1, m);
      for j = uin
        kk = k - nk(j);
        if (kk >= 1)
          wk(j) = residtrace_channels (chans(j), uc(kk, :), 0);
        endif
      endfor
    else
      wk = Wpre(k, :);
    endif
    for s = 1:substeps
      if (any (isv))
        if (velocity_is_y)
          v = xs(1);
        else
          v = A(1, :) * xs + Bc(1, ! isx) * wk(! isx).';
        endif
        wk(isv & ! vy) = sign (v);
        wk(isv & vy) = sign (xs(1) + y_off);
      endif
      if (any (isy))
        yk = xs(1) + y_off;
        p = yk .^ ypw;
        p(yfrac) = sign (yk) * abs (yk) .^ ypw(yfrac);
        wk(isy) = p;
      endif
      xs = Phi * xs + Gam * wk.';
    endfor
  endfor
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

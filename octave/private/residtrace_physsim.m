## -*- texinfo -*-
## @deftypefn {} {[@var{y}, @var{z}] =} residtrace_physsim (@var{model}, @var{u}, @var{Ts})
## Output of a @code{residtrace} model with a physical realisation
## (@code{model.phys}, issue 9) on the input @var{u} (N-by-nu, held over
## each sampling interval), open loop. Two kinds:
## @table @asis
## @item "stop" (a state saturated with its velocity reset)
## F(p) x = sum_j B_j(p) w_j in observable canonical form, x1 = x (the
## output's dynamic part, y = x + c with c the model's output offset),
## x1' = -f1 x1 + x2 (every channel's relative degree at least 2, so the
## velocity x1' is a function of the state). The output is a position
## limited to [phys.lo, phys.hi] (output units): a sub-step that crosses a
## level ends at it with the velocity zero (x1 = L - c, x2 = f1 x1: an
## inelastic end stop); while held there, x1 and x2 stay and the other
## states evolve; the stop is left when the acceleration x2' = -f2 x1 + x3
## + (B w)_2 points away from it. Each sub-step is exact (matrix
## exponential) for the held channels; @code{phys.substeps} sub-steps per
## sampling interval are taken only in the intervals where a level is
## crossed. Starts at rest at x = 0 (the record's level), clipped.
## @item "cascade" (two first-order sections with the nonlinearity at the
## inner node)
## z' = sum_j b_j w_j + d - alpha g(z), 0 <= z <= phys.hi (an inner state
## that overflows), and h' = g(z) - gamma g(h), y = c + h, g = sqrt (two
## tanks with Torricelli outflows; phys.g = "sqrt") or g(s) = s (a linear
## cascade, phys.g = "lin"). Classical Runge-Kutta in
## @code{phys.substeps} sub-steps per sample, the states projected onto
## their bounds after each; starts at rest for the first sample's
## channels (the record is taken to start at rest there).
## @end table
## @var{z}: the inner state ("cascade") or the position x + c ("stop").
## A cell of "cascade" models of one structure (channels, nonlinearity)
## gives their outputs side by side, in one pass over the samples (the
## columns of @var{y}; for a Jacobian).
## @end deftypefn

function [y, z] = residtrace_physsim (model, u, Ts)
  batch = iscell (model);
  if (batch)
    models = model;
    model = models{1};
  endif
  P = model.phys;
  chans = model.channels;
  N = rows (u);
  W = residtrace_channels (chans, u, zeros (N, 1));
  for j = 1:numel (chans)
    k = chans(j).nk;
    if (k > 0)
      W(:, j) = [zeros(k, 1); W(1:end-k, j)];
    endif
  endfor
  switch (P.kind)
    case "stop"
      [y, z] = sim_stop (model, W, Ts);
    case "cascade"
      if (batch)
        [y, z] = sim_cascade (models, W, Ts);
      else
        [y, z] = sim_cascade (model, W, Ts);
      endif
    otherwise
      error ("residtrace:notSupported", "residtrace: realisation '%s'",
             P.kind);
  endswitch
endfunction

function c = out_offset (model)
  c = 0;
  for k = 1:numel (model.out)
    if (strcmp (model.out(k).type, "offset"))
      c += model.out(k).c(1);
    endif
  endfor
endfunction

function [y, pos] = sim_stop (model, W, Ts)
  P = model.phys;
  F = model.F(:).' / model.F(1);
  n = numel (F) - 1;
  m = columns (W);
  Bm = zeros (n, m);
  for j = 1:m
    b = model.channels(j).B(:) / model.F(1);
    Bm(n-numel(b)+1:n, j) = b;
  endfor
  U = W * Bm.';                          # N-by-n forcing of the states
  f = F(2:end);
  A = [-f(:), eye(n, n-1)];
  S = P.substeps;
  [Ad, Gd] = zoh (A, Ts);
  [As, Gs] = zoh (A, Ts / S);
  c = out_offset (model);
  lo = P.lo - c; hi = P.hi - c;          # the levels of x
  ## held: x1, x2 fixed, the states 3..n evolve with x1 at the level
  nh = n - 2;
  if (nh > 0)
    Ah = diag (ones (nh - 1, 1), 1);
    [Ahd, Ghd] = zoh (Ah, Ts);
    [Ahs, Ghs] = zoh (Ah, Ts / S);
  endif
  N = rows (W);
  x = zeros (n, 1);
  held = 0;
  if (0 > hi)
    x(1) = hi; x(2) = f(1) * hi; held = 1;
  elseif (0 < lo)
    x(1) = lo; x(2) = f(1) * lo; held = -1;
  endif
  y = zeros (N, 1);
  for k = 1:N
    y(k) = x(1);
    uk = U(k, :).';
    if (held != 0)
      L = x(1);
      acc = -f(2) * L + uk(2);
      if (n > 2)
        acc += x(3);
      endif
      if (sign (acc) == held || acc == 0)
        if (nh > 0)                      # at the stop the whole interval
          x(3:n) = Ahd * x(3:n) + Ghd * (uk(3:n) - f(3:n).' * L);
        endif
        continue;
      endif
      held = 0;                          # it leaves the stop
    endif
    xn = Ad * x + Gd * uk;
    if (xn(1) <= hi && xn(1) >= lo)
      x = xn;
      continue;
    endif
    ## a level is crossed within the interval: sub-steps
    for s = 1:S
      if (held == 0)
        x = As * x + Gs * uk;
        if (x(1) > hi)
          held = 1; x(1) = hi;
        elseif (x(1) < lo)
          held = -1; x(1) = lo;
        endif
        if (held != 0)
          x(2) = f(1) * x(1);
        endif
      elseif (nh > 0)
        x(3:n) = Ahs * x(3:n) + Ghs * (uk(3:n) - f(3:n).' * x(1));
      endif
    endfor
  endfor
  pos = y + c;
  y = pos;
endfunction

## exact one-step map of x' = A x + v, v held: x+ = Ad x + Gd v
function [Ad, Gd] = zoh (A, h)
  n = rows (A);
  E = expm ([A, eye(n); zeros(n, 2 * n)] * h);
  Ad = E(1:n, 1:n);
  Gd = E(1:n, n+1:end);
endfunction

function [y, zz] = sim_cascade (model, W, Ts)
  ## model may be a cell of models of one structure: their outputs side
  ## by side (the columns of y), in one pass over the samples
  if (! iscell (model))
    model = {model};
  endif
  K = numel (model);
  m = columns (W);
  b = zeros (m, K);
  d = al = ga = top = c = zeros (1, K);
  S = 1;
  for i = 1:K
    Mi = model{i};
    for j = 1:m
      b(j, i) = Mi.channels(j).B(end);
    endfor
    P = Mi.phys;
    d(i) = P.d; al(i) = P.alpha; ga(i) = P.gamma; top(i) = P.hi;
    c(i) = P.c;
    S = max (S, P.substeps);
  endfor
  q = W * b + d;                         # inflow of the inner section
  h = Ts / S;
  sq = strcmp (model{1}.phys.g, "sqrt");
  ## at rest for the first sample's inflow
  q1 = max (q(1, :), 0);
  if (sq)
    z = min ((q1 ./ al) .^ 2, top);
    hh = (sqrt (z) ./ ga) .^ 2;
  else
    z = min (q1 ./ al, top);
    hh = z ./ ga;
  endif
  N = rows (W);
  y = zeros (N, K);
  zz = zeros (N, K);
  for k = 1:N
    y(k, :) = hh; zz(k, :) = z;
    qk = q(k, :);
    if (sq)
      for s = 1:S
        o1 = sqrt (max (z, 0)); a1 = qk - al .* o1;
        b1 = o1 - ga .* sqrt (max (hh, 0));
        za = z + h / 2 * a1; ha = hh + h / 2 * b1;
        o2 = sqrt (max (za, 0)); a2 = qk - al .* o2;
        b2 = o2 - ga .* sqrt (max (ha, 0));
        za = z + h / 2 * a2; ha = hh + h / 2 * b2;
        o3 = sqrt (max (za, 0)); a3 = qk - al .* o3;
        b3 = o3 - ga .* sqrt (max (ha, 0));
        za = z + h * a3; ha = hh + h * b3;
        o4 = sqrt (max (za, 0)); a4 = qk - al .* o4;
        b4 = o4 - ga .* sqrt (max (ha, 0));
        z = min (max (z + h / 6 * (a1 + 2 * a2 + 2 * a3 + a4), 0), top);
        hh = max (hh + h / 6 * (b1 + 2 * b2 + 2 * b3 + b4), 0);
      endfor
    else
      for s = 1:S
        a1 = qk - al .* z; b1 = z - ga .* hh;
        za = z + h / 2 * a1; ha = hh + h / 2 * b1;
        a2 = qk - al .* za; b2 = za - ga .* ha;
        za = z + h / 2 * a2; ha = hh + h / 2 * b2;
        a3 = qk - al .* za; b3 = za - ga .* ha;
        za = z + h * a3; ha = hh + h * b3;
        a4 = qk - al .* za; b4 = za - ga .* ha;
        z = min (z + h / 6 * (a1 + 2 * a2 + 2 * a3 + a4), top);
        hh += h / 6 * (b1 + 2 * b2 + 2 * b3 + b4);
      endfor
    endif
  endfor
  y += c;
endfunction

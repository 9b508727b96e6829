## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {[@var{y}, @var{t}] =} time_response (@var{kind}, @var{fname}, @var{args})
## Step or impulse responses (@var{kind} "step" / "impulse") of the models
## in @var{args} (see @code{parse_sys_args}), plotted without outputs.
## Continuous time: exact at every instant, x(t) from the matrix
## exponential of [A B; 0 0] t (step) or e^(A t) B (impulse), shifted by
## each input's delay; discrete time: the state recursion (unit step,
## unit pulse).  @var{y} is N-by-ny-by-nu (MATLAB's layout) for the first
## model.
## @end deftypefn

function [yout, tout] = time_response (kind, fname, args)
  [sys, styles, tgiven] = parse_sys_args (fname, args);
  if (numel (tgiven) == 1)
    tfinal = tgiven;
    tgiven = [];
  else
    tfinal = [];
  endif
  Y = cell (size (sys));
  T = cell (size (sys));
  for s = 1:numel (sys)
    [a, b, c, d, Ts, delay] = sys_data (sys{s}, fname);
    tmax = max ([tgiven(:); tfinal]);
    if (Ts > 0 && tmax / Ts > 1e7)
      error ([fname ":badInput"],
             "%s: more than 1e7 samples up to t = %g", fname, tmax);
    endif
    t = tgiven;
    if (isempty (t))
      t = default_time (a, Ts, delay, tfinal);
    endif
    Y{s} = response (kind, a, b, c, d, Ts, delay, t);
    if (any (! isfinite (Y{s}(:))))
      error ([fname ":numericalFailure"],
             "%s: the response is not finite up to t = %g", fname, max (t));
    endif
    T{s} = t;
  endfor
  if (nargout > 0)
    yout = Y{1};
    tout = T{1};
    return;
  endif
  [ny, nu] = deal (size (Y{1}, 2), size (Y{1}, 3));
  for i = 1:ny
    for j = 1:nu
      subplot (ny, nu, (i - 1) * nu + j);
      hold on;
      for s = 1:numel (sys)
        if (size (Y{s}, 2) < i || size (Y{s}, 3) < j)
          continue;
        endif
        args = {};
        if (! isempty (styles{s}))
          args = {styles{s}};
        endif
        if (all (diff (T{s}) > 0) && sys_ts (sys{s}) > 0)
          stairs (T{s}, Y{s}(:, i, j), args{:});
        else
          plot (T{s}, Y{s}(:, i, j), args{:});
        endif
      endfor
      hold off;
      grid on;
      if (ny * nu > 1)
        title (sprintf ("From u%d to y%d", j, i));
      else
        title (sprintf ("%s response", [upper(kind(1)), kind(2:end)]));
      endif
    endfor
  endfor
  xlabel ("time (s)");
endfunction

function Ts = sys_ts (sys)
  Ts = get (sys, ifelse_ (isa (sys, "idmodel"), "Ts", "tsam"));
endfunction

function r = ifelse_ (c, a, b)
  if (c)
    r = a;
  else
    r = b;
  endif
endfunction

function t = default_time (a, Ts, delay, tfinal)
  if (isempty (tfinal))
    p = eig (a);
    if (Ts > 0)
      p = log (p(abs (p) > 0)) / Ts;
    endif
    p = p(real (p) < -1e-9);
    if (isempty (p))
      tfinal = 10;
    else
      tfinal = 7 / min (abs (real (p)));
    endif
    tfinal += max ([0; delay(:)]) * max (Ts, 1 * (Ts == 0));
  endif
  if (Ts > 0)
    t = (0:ceil (tfinal / Ts))' * Ts;
  else
    t = linspace (0, tfinal, 401)';
  endif
endfunction

function y = response (kind, a, b, c, d, Ts, delay, t)
  n = rows (a);
  [ny, nu] = size (d);
  N = numel (t);
  y = zeros (N, ny, nu);
  for i = 1:ny
    for j = 1:nu
      if (Ts > 0)
        k = round (t / Ts);                   # sample indices
        K = max (k);
        x = zeros (n, 1);
        yy = zeros (K + 1, 1);
        for m = 0:K
          if (strcmp (kind, "step"))
            u = double (m >= delay(i, j));
          else
            u = double (m == delay(i, j));
          endif
          yy(m+1) = c(i, :) * x + d(i, j) * u;
          x = a * x + b(:, j) * u;
        endfor
        y(:, i, j) = yy(k + 1);
      else
        for m = 1:N
          tau = t(m) - delay(i, j);
          if (tau < 0)
            continue;
          endif
          if (strcmp (kind, "step"))
            E = expm ([a, b(:, j); zeros(1, n + 1)] * tau);
            y(m, i, j) = c(i, :) * E(1:n, n+1) + d(i, j);
          else
            y(m, i, j) = c(i, :) * expm (a * tau) * b(:, j);
          endif
        endfor
      endif
    endfor
  endfor
endfunction

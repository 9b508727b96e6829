## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {[@var{y}, @var{t}] =} time_response (@var{kind}, @var{fname}, @var{args})
## Step or impulse responses (@var{kind} "step" / "impulse") of the models
## in @var{args} (see @code{parse_sys_args}), plotted without outputs.
## Continuous time: exact at every instant, the core's simulation of a
## unit step (simc_mex, copied into this folder at build time), shifted
## by each input's delay; discrete time: the state recursion (unit step,
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
    Y{s} = response (kind, a, b, c, d, Ts, delay, t, fname);
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
  Ts = get (sys, merge (isa (sys, "idmodel"), "Ts", "tsam"));
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

function y = response (kind, a, b, c, d, Ts, delay, t, fname)
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
        y(:, i, j) = continuous_step (kind, a, b(:, j), c(i, :), d(i, j),
                                      t - delay(i, j), fname);
      endif
    endfor
  endfor
endfunction

## The step (or impulse) response of x' = a x + b u, y = c x + d u at the
## times s from the input's onset (0 before it): the core's exact
## simulation of a unit step, held from s = 0 (a step is its own
## zero-order hold). The impulse response c e^(a s) b is the step response
## of (a, b, c a, c b).
function y = continuous_step (kind, a, b, c, d, s, fname)
  y = zeros (numel (s), 1);
  on = s >= 0;
  if (! any (on))
    return;
  endif
  if (strcmp (kind, "impulse"))
    [c, d] = deal (c * a, c * b);
  endif
  if (isempty (a))                      # a static gain
    y(on) = d;
    return;
  endif
  [tk, ~, at] = unique (s(on)(:));      # the times in any order
  lead = tk(1) > 0;                     # the simulation starts at the onset
  if (lead)
    tk = [0; tk];
  endif
  if (numel (tk) == 1)                  # the onset alone
    ys = d;
  else
    try
      ys = simc_mex (fname, "state_space", ones (numel (tk), 1), tk,
                     struct ("a", a, "b", b, "c", c, "d", d));
    catch err
      contsid_rethrow (err, fname);
    end_try_catch
  endif
  y(on) = ys(at + lead);
endfunction

## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn  {} {@var{yout} =} simc_hw (@var{hwmodel}, @var{data})
## @deftypefnx {} {[@dots{}] =} simc_hw (@var{hwmodel}, @var{data}, @var{Cc0}, @var{t_y}, @var{state0})
## @deftypefnx {} {[@dots{}] =} simc_hw (@var{hwmodel}, @var{data}, @var{Cc0}, @var{state0}, @var{t_r}, @var{t_y})
## @deftypefnx {} {[@var{yout}, @var{xout}, @var{uout}, @var{eout}, @var{tout}, @var{yout_nf}] =} simc_hw (@dots{})
## Simulate a continuous-time Hammerstein-Wiener model (CONTSID's
## @code{simc_hw}, as its Hammerstein-Wiener demo calls it:
## @code{[yout,xout,uout,eout,tout] = simc_hw (hwmodel,data_ue,[],[],t_r,t_y)}):
## @example
## ubar = f(u),   xbar = B(s)/A(s) ubar,   x = g^-1(xbar),   y = x + e.
## @end example
##
## @strong{Model} @var{hwmodel}, a struct with fields
## @table @code
## @item ltim
## the linear block, a continuous-time single-input single-output model:
## @code{idpoly ([], Bs, 1, 1, As, "Ts", 0)} as the demo builds it (or
## any model @code{simc} takes: idpoly, idtf, idproc, idss, a struct with
## B and F, a control tf/ss), delays included.
## @item fh_ham
## the input nonlinearity f, a function handle applied to the input
## samples (the demo: @code{@@Ham}).  Or, instead, @code{NL_H}: the
## coefficients [1 alpha_2 .. alpha_L] of f(u) = u + alpha_2 u^2 + ..,
## as @code{hwsrivc}'s @code{Infos.NL_H}.  Neither: f(u) = u.
## @item fh_wie
## the output nonlinearity, a function handle that maps xbar to x (the
## demo: @code{@@Wie}, x = g^-1(xbar)).  Or, instead, @code{NL_W}: the
## coefficients [1 beta_2 .. beta_L] of xbar = g(x) = x + beta_2 x^2 +
## .., as @code{hwsrivc}'s @code{Infos.NL_W}; x is then the real solution
## of g(x) = xbar (unique when g is monotonic; otherwise the one nearest
## the previous sample's).  Neither: x = xbar.
## @end table
## A handle must return one finite real value per sample (an array of the
## size of its argument).
##
## @strong{Data} @var{data}, an @code{iddata} set with one experiment:
## either @code{iddata (e, u, Ts)} (the demo's @code{data_ue}: the output
## channel is the output noise e, the single input u) or, as CONTSID's
## help writes it, input-only @code{iddata ([], [r e], Ts)} (r the input,
## e the optional output noise).  Its sampling instants (or @var{t_r})
## and its InterSample ("zoh" or "foh") apply to the input: f is applied
## to the input samples and ubar is held (zoh) or linear (foh) between
## them, as @code{simc} simulates it (exactly).
##
## @strong{Optional arguments} (empty for the default)
## @table @var
## @item Cc0
## a controller for a closed-loop simulation: not supported (must be
## empty; @code{simc_hw:notSupported}).
## @item state0
## initial state of the linear block in the realisation of @var{xout}
## (default at rest); its free response is added.
## @item t_r
## the N instants of the input samples (default: the data's).
## @item t_y
## the instants at which the output is returned (default @var{t_r});
## increasing, within [t_r(1), Inf).  The noise e must then have one
## sample per instant of @var{t_y}.
## @end table
## With five arguments the order is CONTSID's documented one (Cc0, t_y,
## state0); with six, the demo's (Cc0, state0, t_r, t_y).
##
## @strong{Outputs}, one row per instant of @var{tout} = @var{t_y}:
## @var{yout} the output y = x + e, @var{xout} the state of the linear
## block in the control package's realisation @code{ss (tf (Bs, As))}
## (so that @code{xout * C'} is xbar, C of that realisation, as the demo
## uses it; a state-space ltim keeps its own realisation), @var{uout}
## the input u at @var{tout} (held or interpolated), @var{eout} the
## noise, @var{tout}, @var{yout_nf} the noise-free output x.
##
## The state needs the control package (for the realisation); the other
## outputs do not.  Errors: @code{simc_hw:badInput} (not a struct, no or
## a discrete-time ltim, a nonlinearity given twice, a handle that returns
## a wrong size or non-finite values, times not increasing),
## @code{simc_hw:dimensionMismatch} (data, instants and noise lengths),
## @code{simc_hw:notSupported} (closed loop, several inputs or outputs,
## process noise e2); the linear simulation's errors are @code{simc}'s.
## @seealso{simc, hwsrivc, Ham, Wie}
## @end deftypefn

function varargout = simc_hw (varargin)
  varargout = contsid_guard ("simc_hw", @simc_hw_body, nargout, varargin);
endfunction

function [yout, xout, varargout] = simc_hw_body (varargin)
  contsid_nargchk ("simc_hw", nargin, nargout, [2 6], 6);
  fname = "simc_hw";
  hwmodel = varargin{1};
  data = varargin{2};
  opt = cell (1, 4);                     # Cc0, state0, t_r, t_y
  switch (nargin)
    case 3
      opt(1) = varargin(3);
    case 4
      opt([1 4]) = varargin(3:4);
    case 5
      opt([1 4 2]) = varargin(3:5);
    case 6
      opt(1:4) = varargin(3:6);
  endswitch
  [Cc0, state0, t_r, t_y] = opt{:};
  if (! isempty (Cc0))
    error ("simc_hw:notSupported",
           "simc_hw: closed-loop simulation (Cc0) is not supported");
  endif
  [ltim, f_ham, f_wie] = read_model (fname, hwmodel);
  [u, e, t_data, intersample] = read_data (fname, data);
  N = rows (u);
  if (isempty (t_r))
    t_r = t_data;
  else
    t_r = instants (fname, t_r, "t_r");
    if (numel (t_r) != N)
      error ("simc_hw:dimensionMismatch",
             "simc_hw: 't_r' has %d instants for %d input samples",
             numel (t_r), N);
    endif
  endif
  if (isempty (t_y))
    t_y = t_r;
  else
    t_y = instants (fname, t_y, "t_y");
    if (t_y(1) < t_r(1))
      error ("simc_hw:badInput",
             "simc_hw: 't_y' starts (%g) before the input (%g)",
             t_y(1), t_r(1));
    endif
  endif
  if (isempty (e))
    e = zeros (numel (t_y), 1);
  elseif (numel (e) != numel (t_y))
    error ("simc_hw:dimensionMismatch",
           "simc_hw: the noise has %d samples for %d output instants",
           numel (e), numel (t_y));
  endif

  ubar_r = apply (fname, f_ham, u, "the input nonlinearity");
  ## every instant: the input's and the output's
  [tt, ~, pos] = unique ([t_r; t_y]);
  ir = pos(1:N);
  iy = pos(N+1:end);
  if (numel (tt) == N)
    ubar = ubar_r;
    uu = u;
  else
    ubar = between (t_r, ubar_r, tt, intersample);
    uu = between (t_r, u, tt, intersample);
  endif
  tsim = tt - tt(1);
  dt = diff (tsim);
  if (! isempty (dt) && max (abs (dt - mean (dt))) <= 1e-9 * mean (dt))
    tsim = mean (dt);                    # regular: simc's exact delays
  elseif (isempty (dt))
    tsim = 1;
  endif
  xbar = simc (ltim, ubar, tsim, "InterSample", intersample);
  if (nargout > 1 || ! isempty (state0))
    [X, c, d] = states (fname, ltim, ubar, tsim, intersample);
    if (! isempty (state0))
      [X, xbar] = add_free (fname, X, xbar, state0, ltim, tt - tt(1), c);
    endif
    xout = X(iy, :);
  endif
  x = apply (fname, f_wie, xbar(iy), "the output nonlinearity");
  yout = x + e(:);
  varargout = {uu(iy), e(:), t_y, x};
  varargout = varargout(1:max (0, nargout - 2));
endfunction

function [ltim, f_ham, f_wie] = read_model (fname, hw)
  if (! isstruct (hw) || ! isscalar (hw))
    error ("simc_hw:badInput", "simc_hw: 'hwmodel' must be a scalar struct");
  endif
  known = {"ltim", "fh_ham", "fh_wie", "NL_H", "NL_W"};
  extra = setdiff (fieldnames (hw), known);
  if (! isempty (extra))
    error ("simc_hw:badInput", "simc_hw: unknown field hwmodel.%s", extra{1});
  endif
  if (! isfield (hw, "ltim") || isempty (hw.ltim))
    error ("simc_hw:badInput", "simc_hw: 'hwmodel.ltim' (the linear block) is missing");
  endif
  ltim = hw.ltim;
  if (isa (ltim, "idmodel") && ! isct (ltim))
    error ("simc_hw:badInput",
           "simc_hw: 'hwmodel.ltim' must be a continuous-time model");
  endif
  if (isa (ltim, "idmodel"))
    [ny, nu] = size (ltim);
    if (ny != 1 || nu != 1)
      error ("simc_hw:notSupported",
             "simc_hw: the linear block must have one input and one output");
    endif
  endif
  f_ham = block (hw, "fh_ham", "NL_H", "polynomial");
  f_wie = block (hw, "fh_wie", "NL_W", "inverse");
endfunction

## A nonlinearity: a handle, or coefficients [1 c2 .. cL] of a polynomial
## without constant term (applied as it is, or inverted).
function f = block (hw, handle, coef, use)
  has_h = isfield (hw, handle) && ! isempty (hw.(handle));
  has_c = isfield (hw, coef) && ! isempty (hw.(coef));
  if (has_h && has_c)
    error ("simc_hw:badInput",
           "simc_hw: give hwmodel.%s or hwmodel.%s, not both", handle, coef);
  endif
  if (has_h)
    f = hw.(handle);
    if (! is_function_handle (f))
      error ("simc_hw:badInput",
             "simc_hw: 'hwmodel.%s' must be a function handle", handle);
    endif
  elseif (has_c)
    c = hw.(coef);
    if (! isnumeric (c) || ! isreal (c) || ! isvector (c)
        || any (! isfinite (c)) || all (c == 0))
      error ("simc_hw:badInput",
             "simc_hw: 'hwmodel.%s' must be real finite coefficients", coef);
    endif
    c = double (c(:).');
    if (strcmp (use, "polynomial"))
      f = @(u) polyval ([fliplr(c), 0], u);
    else
      f = @(v) contsid_poly_inverse ("simc_hw", c, v);
    endif
  else
    f = [];
  endif
endfunction

function [u, e, t, intersample] = read_data (fname, data)
  if (! isa (data, "iddata"))
    error ("simc_hw:badInput", "simc_hw: 'data' must be an iddata set");
  endif
  [~, ny, nu, ne] = size (data);
  if (ne != 1)
    error ("simc_hw:badInput", "simc_hw: the data must hold one experiment");
  endif
  info = samplinginfo (data);
  intersample = info.InterSample;
  if (iscell (intersample))
    intersample = intersample{1};
  endif
  y = get (data, "OutputData");
  uu = get (data, "InputData");
  if (iscell (y))
    y = y{1};
    uu = uu{1};
  endif
  if (ny == 1 && nu == 1)
    u = uu;
    e = y;
  elseif (ny == 0 && (nu == 1 || nu == 2))
    u = uu(:, 1);
    e = uu(:, 2:end);
  elseif (ny == 0 && nu > 2)
    error ("simc_hw:notSupported",
           "simc_hw: process noise (a third input column, e2) is not supported");
  else
    error ("simc_hw:notSupported",
           ["simc_hw: the data must be iddata (e, u, Ts) or ", ...
            "iddata ([], [r e], Ts) with one input, not %d output(s) and ", ...
            "%d input(s)"], ny, nu);
  endif
  u = double (u);
  e = double (e);
  if (isempty (u) || any (! isfinite (u(:))) || any (! isfinite (e(:))))
    error ("simc_hw:badInput", "simc_hw: the data must be finite");
  endif
  if (info.Uniform)
    if (! (info.Ts > 0))
      error ("simc_hw:badInput", "simc_hw: the data have no sampling interval");
    endif
    t = (0:rows (u) - 1)' * info.Ts;
  else
    t = info.SamplingInstants(:);
  endif
endfunction

function t = instants (fname, t, name)
  if (! isnumeric (t) || ! isreal (t) || ! isvector (t)
      || any (! isfinite (t)))
    error ("simc_hw:badInput",
           "simc_hw: '%s' must be a real finite vector", name);
  endif
  t = double (t(:));
  if (any (diff (t) <= 0))
    error ("simc_hw:badInput", "simc_hw: '%s' must be increasing", name);
  endif
endfunction

function v = apply (fname, f, v, what)
  if (isempty (f))
    return;
  endif
  try
    w = f (v);
  catch err
    error ("simc_hw:badInput", "simc_hw: %s failed: %s", what, err.message);
  end_try_catch
  if (! isnumeric (w) || ! isreal (w) || numel (w) != numel (v)
      || any (! isfinite (w(:))))
    error ("simc_hw:badInput",
           "simc_hw: %s must return one finite real value per sample", what);
  endif
  v = reshape (double (w), size (v));
endfunction

## Signal sampled at t_r seen at the instants tt: held (zoh) or linear
## (foh) between samples, held after the last.
function w = between (t_r, v, tt, intersample)
  if (strcmpi (intersample, "foh") && numel (t_r) > 1)
    w = interp1 (t_r, v, tt, "linear", "extrap");
    after = tt > t_r(end);
    w(after, :) = repmat (v(end, :), sum (after), 1);
  else
    k = lookup (t_r, tt);
    w = v(max (k, 1), :);
  endif
endfunction

## The linear block's state in the control package's realisation of its
## transfer function (or its own state space), from the same simulator:
## each state is the output of (sI - A)^-1 B.
function [X, c, d] = states (fname, ltim, ubar, tsim, intersample)
  m = contsid_model (fname, ltim);
  if (m.ny != 1 || m.nu != 1)
    error ("simc_hw:notSupported",
           "simc_hw: the linear block must have one input and one output");
  endif
  if (strcmp (m.kind, "ss"))
    a = m.a; b = m.b; c = m.c; d = m.d;
  else
    [a, b, c, d] = ssdata (ss (idtf (m.B{1}, m.F{1})));
  endif
  n = rows (a);
  if (n == 0)
    X = zeros (rows (ubar), 0);
    return;
  endif
  delay = m.delay(1);
  if (isnan (delay))                     # a delay in samples (struct nk)
    if (! isscalar (tsim))
      error ("simc_hw:notSupported",
             "simc_hw: a delay in samples needs regularly sampled instants");
    endif
    delay = m.nk(1) * tsim;
  endif
  S = idss (a, b, eye (n), zeros (n, 1), "InputDelay", delay);
  X = simc (S, ubar, tsim, "InterSample", intersample);
endfunction

function [X, xbar] = add_free (fname, X, xbar, x0, ltim, t, c)
  n = columns (X);
  if (! isnumeric (x0) || ! isreal (x0) || numel (x0) != n
      || any (! isfinite (x0(:))))
    error ("simc_hw:badInput",
           "simc_hw: 'state0' must be %d finite real values", n);
  endif
  m = contsid_model (fname, ltim);
  if (strcmp (m.kind, "ss"))
    a = m.a;
  else
    a = ssdata (ss (idtf (m.B{1}, m.F{1})));
  endif
  free = zeros (numel (t), n);
  for k = 1:numel (t)
    free(k, :) = (expm (a * t(k)) * x0(:)).';
  endfor
  X += free;
  xbar += free * c.';
endfunction

%!shared hw, Ts, N, u, e, t
%! rand ("state", 4); randn ("state", 4);
%! Ts = 5e-3; N = 2000;
%! u = 0.5 * kron (2 * rand (5, 1) - 1, ones (400, 1));
%! e = 0.03 * randn (N, 1);
%! t = (0:N-1)' * Ts;
%! hw.ltim = idpoly ([], 1, 1, 1, [1 2], "Ts", 0);
%! hw.fh_ham = @Ham;
%! hw.fh_wie = @Wie;

%!test  # the demo's call: each block against its definition
%! data_ue = iddata (e, u, Ts);
%! data_ue.SamplingInstants = t;
%! [y, x, uo, eo, to, ynf] = simc_hw (hw, data_ue, [], [], t, t);
%! assert (to, t); assert (uo, u); assert (eo, e);
%! xbar = simc (idpoly (1, 1, 1, 1, [1 2], 0, 0),
%!              iddata ([], u - 2 * u.^2 + 0.8 * u.^3, Ts));
%! ## g(x) = xbar for the noise-free output, y = x + e
%! assert (ynf + 1.5 * ynf.^2 + ynf.^3, xbar, 1e-12);
%! assert (y, ynf + e, 1e-15);
%! ## the demo's xbar = xout * C' with C of control's ss (tf (Bs, As))
%! pkg load control
%! S = ss (tf (1, [1 2]));
%! assert (x * S.c', xbar, 1e-12);
%! ## piecewise-constant input: the exact first-order step responses
%! ## (u(401) acts from sample 401 on)
%! k = 402:800; ub = u(401) - 2 * u(401)^2 + 0.8 * u(401)^3;
%! ref = xbar(401) * exp (-2 * (k - 401)' * Ts) ...
%!       + ub / 2 * (1 - exp (-2 * (k - 401)' * Ts));
%! assert (xbar(k), ref, 1e-12);

%!test  # coefficients as hwsrivc's Infos give them = the handles
%! data = iddata ([], [u e], Ts);
%! y1 = simc_hw (hw, data);
%! hw2.ltim = hw.ltim; hw2.NL_H = [1; -2; 0.8]; hw2.NL_W = [1; 1.5; 1];
%! [y2, ~, ~, e2] = simc_hw (hw2, data);
%! assert (y2, y1, 1e-12);
%! assert (e2, e);
%! ## no nonlinearity: simc of the linear block
%! [y3, ~, ~, ~, ~, ynf] = simc_hw (struct ("ltim", hw.ltim), iddata ([], u, Ts));
%! assert (y3, simc (hw.ltim, iddata ([], u, Ts)), 1e-15);

%!test  # a non-monotonic g (quadratic): the branch through the origin
%! h.ltim = idpoly (1, 1, 1, 1, [1 2], 0, 0); h.NL_W = [1 0.5];
%! uu = 0.4 * sin ((0:199)' * 0.05);
%! y = simc_hw (h, iddata ([], uu, 0.05));
%! xbar = simc (h.ltim, uu, 0.05);
%! assert (y, -1 + sqrt (1 + 2 * xbar), 1e-12);
%! h.NL_W = [1 0 1];                   # x + x^3, monotonic
%! assert (simc_hw (h, iddata ([], uu, 0.05)) + ...
%!         simc_hw (h, iddata ([], uu, 0.05)) .^ 3, xbar, 1e-12);
%! h.NL_W = [-1 0 0 0];                # trailing zeros: g(x) = -x
%! assert (simc_hw (h, iddata ([], uu, 0.05)), -xbar, 1e-14);
%! h.NL_W = [0 1];                     # x^2 = xbar < 0 has no real root
%! fail ("simc_hw (h, iddata ([], -abs (uu) - 0.1, 0.05))",
%!       "no value");

%!test  # a delay between samples: the states carry it too
%! pkg load control
%! G = idtf ([1 3], [1 2 5], "IODelay", 0.013);
%! h.ltim = G; h.NL_H = [1 0.5];
%! uu = sin ((0:299)' * 0.03);
%! [y, x] = simc_hw (h, iddata ([], uu, 0.01, "InterSample", "foh"));
%! assert (y, simc (G, uu + 0.5 * uu.^2, 0.01, "InterSample", "foh"), 1e-14);
%! [a, b, c] = ssdata (ss (tf ([1 3], [1 2 5])));
%! assert (x * c.', y, 1e-10);

%!test  # output instants between input samples, a state0
%! pkg load control
%! G = idtf ([1 3], [1 2 5]);
%! h.ltim = G; h.NL_H = [1 0.5];
%! Ts2 = 0.01; n = 300; uu = sin ((0:n-1)' * Ts2 * 3);
%! tr = (0:n-1)' * Ts2; ty = tr(1:10:end) + 0.004;
%! [y, x, uo, ~, to] = simc_hw (h, iddata ([], uu, Ts2), [], [], tr, ty);
%! assert (to, ty); assert (uo, uu(1:10:end));    # held (zoh)
%! ## on the fine grid of both instants: the same model through simc
%! tt = unique ([tr; ty]); k = lookup (tr, tt);
%! ub = uu(k) + 0.5 * uu(k).^2;
%! ## tt is irregular: compare with a 1 ms regular grid holding ub
%! tf_ = (0:2990)' * 1e-3; kf = lookup (tr, tf_ + 1e-12);
%! yf = simc (G, uu(kf) + 0.5 * uu(kf).^2, 1e-3);
%! [~, ia] = ismember (round (ty * 1e3), round (tf_ * 1e3));
%! assert (y, yf(ia), 1e-10);
%! [a, b, c, d] = ssdata (ss (tf ([1 3], [1 2 5])));
%! assert (x * c.', y, 1e-10);
%! ## a free response from state0
%! x0 = [0.3; -0.2];
%! [yz, xz] = simc_hw (h, iddata ([], uu, Ts2), [], x0, tr, ty);
%! for i = 1:numel (ty)
%!   assert (xz(i, :).', x(i, :).' + expm (a * ty(i)) * x0, 1e-10);
%! endfor
%! assert (yz, y + xz * c.' - x * c.', 1e-10);

%!error id=simc_hw:badInput simc_hw (hw)
%!error id=simc_hw:badInput simc_hw (1, iddata ([], u, Ts))
%!error id=simc_hw:badInput simc_hw (struct ("fh_ham", @Ham), iddata ([], u, Ts))
%!error id=simc_hw:badInput simc_hw (setfield (hw, "foo", 1), iddata ([], u, Ts))
%!error id=simc_hw:badInput simc_hw (setfield (hw, "NL_H", [1 2]), iddata ([], u, Ts))
%!error id=simc_hw:badInput simc_hw (setfield (hw, "fh_ham", 3), iddata ([], u, Ts))
%!error id=simc_hw:badInput simc_hw (setfield (hw, "fh_ham", @(u) [u; u]), iddata ([], u, Ts))
%!error id=simc_hw:badInput simc_hw (setfield (hw, "fh_wie", @(x) x / 0), iddata ([], u, Ts))
%!error id=simc_hw:badInput simc_hw (struct ("ltim", hw.ltim, "NL_W", [0 0]), iddata ([], u, Ts))
%!error id=simc_hw:badInput simc_hw (struct ("ltim", idpoly (1, [0 1], 1, 1, [1 -0.5], 1, 0.1)), iddata ([], u, Ts))
%!error id=simc_hw:badInput simc_hw (hw, [u e])
%!error id=simc_hw:badInput simc_hw (hw, iddata ([], u, Ts), [], [], flipud (t), t)
%!error id=simc_hw:badInput simc_hw (hw, iddata ([], u, Ts), [], [], t, t - 1)
%!error id=simc_hw:badInput simc_hw (hw, iddata ([], u, Ts), [], [1 2 3], t, t)
%!error id=simc_hw:dimensionMismatch simc_hw (hw, iddata ([], u, Ts), [], [], t(1:10), t)
%!error id=simc_hw:dimensionMismatch simc_hw (hw, iddata (e, u, Ts), [], t(1:10))
%!error id=simc_hw:notSupported simc_hw (hw, iddata ([], u, Ts), 1)
%!error id=simc_hw:notSupported simc_hw (hw, iddata ([], [u e e], Ts))
%!error id=simc_hw:notSupported simc_hw (hw, iddata ([e e], u, Ts))
%!error id=simc_hw:badInput simc_hw (hw, iddata ([], u, Ts), [], [], [], [], 1)
%!error id=simc_hw:badInput [a, b, c, d, e, f, g] = simc_hw (hw, iddata ([], u, Ts))

%!demo
%! ## CONTSID's Hammerstein-Wiener demo: f = Ham, G = 1/(s + 2), g^-1 = Wie
%! Ts = 5e-3; N = 5000; t = (0:N-1)' * Ts;
%! u = 0.5 * kron (2 * rand (13, 1) - 1, ones (400, 1)); u = u(1:N);
%! e = 0.03 * randn (N, 1);
%! hwmodel.ltim = idpoly ([], 1, 1, 1, [1 2], "Ts", 0);
%! hwmodel.fh_ham = @Ham; hwmodel.fh_wie = @Wie;
%! data_ue = iddata (e, u, Ts);
%! [yout, xout, uout, eout, tout] = simc_hw (hwmodel, data_ue, [], [], t, t);
%! subplot (2, 1, 1); plot (tout, yout); ylabel ("y");
%! subplot (2, 1, 2); plot (tout, uout); ylabel ("u"); xlabel ("time");

## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {[@var{y}, @var{u}] =} sineresp (@var{M}, @var{w}, @var{t})
## Exact steady-state response of a stable continuous-time model to the
## multisine input
## @example
## u(t) = sin (w_1 t) + sin (w_2 t) + .. + sin (w_n t),
## @end example
## as CONTSID's @code{sineresp} (its advantage7 demo:
## @code{[y, u] = sineresp (M0, w, t)}): for each frequency the response
## is |H(j w_i)| sin (w_i t + arg H(j w_i)), H the model's frequency
## response (@code{freqresp}, delays included), and
## @example
## y(t) = sum_i |H(j w_i)| sin (w_i t + arg H(j w_i)).
## @end example
## No transient: the output at t = 0 is already periodic (use @code{simc}
## for the response from rest).  Exact at every instant, so the data suit
## any intersample assumption (the demo contrasts ZOH and FOH models).
##
## @var{M}: a continuous-time @code{idpoly}, @code{idtf}, @code{idss},
## @code{idproc} or a control package @code{tf}/@code{ss}/@code{zpk}
## with one input and all its poles in the open left half-plane (no
## steady state otherwise).  @var{w}: the frequencies in rad/s, a real
## vector of finite values >= 0.  @var{t}: the instants (a real finite
## vector, any spacing).  @var{y} is numel(t)-by-ny, @var{u} a column.
## @seealso{simc, freqresp, idinput}
## @end deftypefn

function varargout = sineresp (varargin)
  varargout = contsid_guard ("sineresp", @sineresp_body, nargout, varargin);
endfunction

function [y, u, varargout] = sineresp_body (varargin)
  contsid_nargchk ("sineresp", nargin, nargout, [3 3], 2);
  [M, w, t] = varargin{:};
  if (isa (M, "idfrd") || isa (M, "iddata"))
    error ("sineresp:notSupported",
           "sineresp: M must be a parametric model, not %s", class (M));
  endif
  if (! (isa (M, "idmodel") || isa (M, "lti")))
    error ("sineresp:badInput",
           "sineresp: M must be an idpoly, idtf, idss, idproc or lti model");
  endif
  if (isa (M, "idmodel"))
    continuous = isct (M);
  else
    continuous = (M.tsam == 0);
  endif
  if (! continuous)
    error ("sineresp:notSupported",
           "sineresp: M must be a continuous-time model");
  endif
  [ny, nu] = size (M);
  if (nu != 1)
    error ("sineresp:notSupported",
           "sineresp: M must have one input, it has %d", nu);
  endif
  if (! isnumeric (w) || ! isreal (w) || isempty (w) || ! isvector (w)
      || any (! isfinite (w)) || any (w < 0))
    error ("sineresp:badInput",
           "sineresp: 'w' must be a vector of finite frequencies >= 0");
  endif
  if (! isnumeric (t) || ! isreal (t) || isempty (t) || ! isvector (t)
      || any (! isfinite (t)))
    error ("sineresp:badInput",
           "sineresp: 't' must be a non-empty real finite vector");
  endif
  p = pole (M);
  if (any (! isfinite (p)) || any (real (p) >= 0))
    error ("sineresp:badInput",
           ["sineresp: M must be stable (poles in Re s < 0): no steady ", ...
            "state, max Re(pole) = %g"], max (real (p)));
  endif
  w = double (w(:)).';
  t = double (t(:));
  H = reshape (freqresp (M, w), ny, numel (w));
  if (any (! isfinite (H(:))))
    error ("sineresp:numericalFailure",
           "sineresp: the frequency response is not finite");
  endif
  phase = t * w;                          # N-by-n
  u = sum (sin (phase), 2);
  y = zeros (numel (t), ny);
  for i = 1:ny
    y(:, i) = sum (abs (H(i, :)) .* sin (phase + arg (H(i, :))), 2);
  endfor
endfunction

%!test  # one sine: amplitude and phase of the polynomials at j w
%! M = idpoly (1, 0.5, 1, 1, [1 0.5], "Ts", 0);
%! t = (0:0.1:20)';
%! for w = [0.1 1 3]
%!   [y, u] = sineresp (M, w, t);
%!   H = 0.5 / (1i * w + 0.5);
%!   assert (u, sin (w * t), 1e-14);
%!   assert (y, abs (H) * sin (w * t + angle (H)), 1e-14);
%! endfor

%!test  # a long lsim run from rest reaches the same steady state
%! pkg load control
%! G = tf ([1 4], [1 2.4 4]);
%! M = idtf ([1 4], [1 2.4 4], "IODelay", 0.35);
%! w = 2 * pi * [0.01:0.1:0.5];
%! dt = 1e-3; T = 60;
%! t = (0:dt:T)';
%! ## lsim interpolates the samples linearly (FOH): the interpolation
%! ## error of the sines is below sum (w.^2) dt^2 / 8 = 1e-6
%! ud = sum (sin ((t - 0.35) * w), 2) .* (t >= 0.35);
%! ysim = lsim (G, ud, t);
%! late = t > 40;                          # transient < e^(-1.2*40)
%! [y, u] = sineresp (M, w, t(late));
%! printf ("sineresp vs lsim: max error %.2e\n", max (abs (y - ysim(late))));
%! assert (y, ysim(late), 1e-5);
%! assert (u, sum (sin (t(late) * w), 2), 1e-12);

%!test  # idss with two outputs, control ss, w = 0
%! a = [-1 2; -2 -3]; b = [1; 0.5]; c = [1 0; 0.3 1]; d = [0; 0.1];
%! t = linspace (0, 5, 7)';
%! w = [0 0.7 2];
%! y = sineresp (idss (a, b, c, d), w, t);
%! assert (size (y), [7 2]);
%! yref = zeros (7, 2);
%! for k = 2:3
%!   H = c / (1i * w(k) * eye (2) - a) * b + d;
%!   yref += abs (H).' .* sin (w(k) * t + angle (H).');
%! endfor
%! assert (y, yref, 1e-13);
%! pkg load control
%! assert (sineresp (ss (a, b, c, d), w, t), yref, 1e-13);

%!error id=sineresp:badInput sineresp (idtf (1, [1 1]), 1)
%!error id=sineresp:badInput sineresp (1, 1, 1)
%!error id=sineresp:badInput sineresp (idtf (1, [1 -1]), 1, 1)
%!error id=sineresp:badInput sineresp (idtf (1, [1 0]), 1, 1)
%!error id=sineresp:badInput sineresp (idtf (1, [1 1]), -1, 1)
%!error id=sineresp:badInput sineresp (idtf (1, [1 1]), [], 1)
%!error id=sineresp:badInput sineresp (idtf (1, [1 1]), 1, NaN)
%!error id=sineresp:badInput sineresp (idtf (1, [1 1]), 1, "t")
%!error id=sineresp:notSupported sineresp (idpoly (1, [0 1], 1, 1, [1 -0.5], 1, 0.1), 1, 1)
%!error id=sineresp:notSupported sineresp (idss (-eye (2), eye (2), [1 1], [0 0]), 1, 1)
%!error id=sineresp:notSupported sineresp (idfrd (1, 1), 1, 1)
%!error id=sineresp:badInput [a, b, c] = sineresp (idtf (1, [1 1]), 1, 1)

%!demo
%! ## CONTSID's advantage7: a first-order system, multisine input
%! T = 2; M0 = idpoly (1, 1/T, 1, 1, [1 1/T], "Ts", 0);
%! Ts = T / 4; t = (0:499)' * Ts;
%! [y, u] = sineresp (M0, 2 * pi * [0.01:0.1:0.5], t);
%! plot (t, [u y]); legend ("u", "y"); xlabel ("time (s)");

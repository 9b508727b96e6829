## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn  {} {@var{wb} =} bandwidthc (@var{M})
## @deftypefnx {} {@var{wb} =} bandwidthc (@var{B}, @var{F})
## @deftypefnx {} {@var{wb} =} bandwidthc (@dots{}, "wmin", @var{wmin})
## @deftypefnx {} {[@var{wb}, @var{kind}, @var{gref}] =} bandwidthc (@dots{})
## Bandwidth (rad/s) of a continuous-time transfer function G(p) =
## B(p)/F(p), defined so that it also serves band-pass models and models
## with integrators; used by @code{svfcutoff} to suggest the SVF cut-off
## lambda_svf (thesis sec. 3.1.2).
##
## @var{M} is an @code{idpoly} (from @code{srivc}, @dots{}), @code{idtf}
## or @code{idproc} model, an @code{idctm}, a struct with fields @code{B}
## and @code{F}, or a control-package @code{tf}; or give the coefficient
## rows @var{B} and @var{F} in descending powers of p.
## One input only.
##
## @strong{Definition.} Poles and zeros whose magnitude is at most
## @var{wmin} are taken as lying at the origin: such a root cannot be told
## from p = 0 within the frequencies a record resolves (@code{svfcutoff}
## passes 2 pi / T, T the length of a segment). Default @var{wmin}: 1e-6
## times the largest root magnitude of F and B. With k = (zeros at the
## origin) - (poles at the origin) and G0(p) the model without these roots:
## @table @asis
## @item k <= 0 (@var{kind} @qcode{"lowpass"}, or @qcode{"integrator"} if k < 0)
## reference gain @var{gref} = |G0(0)|, the low-frequency gain of the model
## without its integrators, and @var{wb} the frequency above which
## |G0(j w)| stays below @var{gref}/sqrt(2). For a low-pass model this is
## the usual -3 dB bandwidth relative to the static gain (MATLAB's
## @code{bandwidth}); for K/(p (p + a)) it is a.
## @item k > 0 (@var{kind} @qcode{"bandpass"})
## reference gain @var{gref} = the peak of |G(j w)| over w, and @var{wb} the
## upper -3 dB frequency: above it |G(j w)| stays below @var{gref}/sqrt(2).
## For b0 p / (p^2 + a1 p + a2) this is a1/2 + sqrt (a1^2/4 + a2).
## @end table
## When the gain does not fall 3 dB below @var{gref} at high frequencies
## (a biproper model whose high-frequency gain is within 3 dB of
## @var{gref}, e.g. p/(p + a)), @var{kind} gets the suffix
## @qcode{"-noedge"} and @var{wb} is the largest corner frequency, the
## largest magnitude of the remaining roots of F and B; it is NaN when no
## root remains (a pure gain, integrator or differentiator).
##
## The edge is located on a logarithmic grid and refined by @code{fzero}
## on log w, to a relative accuracy of about 1e-10.
##
## @strong{Example}
## @example
## wb = bandwidthc (4, [1 2.4 4])     # 2nd order, zeta = 0.6, wn = 2
## wb = bandwidthc ([5 0], [1 2 25])  # band-pass: 1 + sqrt (26)
## @end example
## @seealso{svfcutoff, srivc, bode4frozensys}
## @end deftypefn

function varargout = bandwidthc (varargin)
  varargout = contsid_guard ("bandwidthc", @bandwidthc_body, nargout, varargin);
endfunction

function [wb, kind, gref, varargout] = bandwidthc_body (varargin)
  contsid_nargchk ("bandwidthc", nargin, nargout, [0 Inf], 3);
  fname = "bandwidthc";
  if (nargin < 1)
    error ("bandwidthc:badInput", "bandwidthc: expected a model or B and F");
  endif
  [B, F, rest] = read_model (varargin);
  wmin = [];
  if (! isempty (rest))
    if (numel (rest) != 2 || ! ischar (rest{1})
        || ! strcmpi (rest{1}, "wmin"))
      error ("bandwidthc:badOption",
             "bandwidthc: the only option is \"wmin\", followed by its value");
    endif
    wmin = rest{2};
    if (! isnumeric (wmin) || ! isreal (wmin) || ! isscalar (wmin)
        || ! isfinite (wmin) || wmin < 0)
      error ("bandwidthc:badInput",
             "bandwidthc: wmin must be a finite real scalar >= 0");
    endif
  endif

  z = roots (B);
  p = roots (F);
  if (isempty (wmin))
    wmin = 1e-6 * max ([abs(z); abs(p); 0]);
  endif
  at0_z = abs (z) <= wmin;
  at0_p = abs (p) <= wmin;
  k = sum (at0_z) - sum (at0_p);
  z = reshape (z(! at0_z), [], 1);
  p = reshape (p(! at0_p), [], 1);
  gain = abs (B(1) / F(1));
  ## |G(jw)| without the roots at the origin, times w^k for band-pass models.
  kk = max (k, 0);
  mag = @(w) gain * w .^ kk .* prod (abs (1i * w - z), 1) ...
             ./ prod (abs (1i * w - p), 1);
  reldeg = numel (p) - numel (z) - kk;     # high-frequency slope (-20 dB/dec)
  corners = [abs(z); abs(p)];
  if (isempty (corners))
    lo = max (wmin, 1);
    hi = lo;
  else
    lo = min (corners);
    hi = max (corners);
  endif
  w = logspace (log10 (lo) - 3, log10 (hi) + 3, 3000);
  m = eval_mag (mag, w);
  if (k <= 0)
    gref = gain * prod (abs (z)) / prod (abs (p));
    if (k == 0)
      kind = "lowpass";
    else
      kind = "integrator";
    endif
  else
    kind = "bandpass";
    [gref, i] = max (m);
    if (i > 1 && i < numel (w))
      f = @(lw) -eval_mag (mag, 10 .^ lw);
      [lw, fv] = fminbnd (f, log10 (w(i-1)), log10 (w(i+1)));
      gref = max (gref, -fv);
    endif
    if (reldeg == 0)
      gref = max (gref, gain);
    endif
  endif
  thresh = gref / sqrt (2);
  if (reldeg <= 0 && gain >= thresh * (1 - 1e-12))
    ## No roll-off below the reference: fall back to the largest corner.
    kind = [kind "-noedge"];
    if (isempty (corners))
      wb = NaN;
    else
      wb = hi;
    endif
    return;
  endif
  ## Widen the grid until the gain has fallen below the threshold.
  while (m(end) >= thresh)
    w = [w, w(end) * logspace(0.01, 3, 300)];
    m = [m, eval_mag(mag, w(end-299:end))];
    if (w(end) > 1e12 * max (hi, 1))
      error ("bandwidthc:numericalFailure",
             "bandwidthc: the gain does not roll off below the -3 dB level");
    endif
  endwhile
  ## The grid starts three decades below the lowest corner, where the gain
  ## is the reference (low-pass) or includes the peak (band-pass).
  i = find (m >= thresh, 1, "last");
  g = @(lw) log (eval_mag (mag, 10 .^ lw)) - log (thresh);
  lw = fzero (g, log10 ([w(i), w(i+1)]), optimset ("TolX", 1e-12));
  wb = 10 ^ lw;
endfunction

function m = eval_mag (mag, w)
  m = reshape (mag (w(:).'), size (w));
endfunction

function [B, F, rest] = read_model (args)
  M = args{1};
  rest = args(2:end);
  if (isobject (M) || isstruct (M))
    m = contsid_model ("bandwidthc", M);
    if (! strcmp (m.kind, "tf") || m.ny != 1 || m.nu != 1 || m.Ts > 0)
      error ("bandwidthc:badInput",
             "bandwidthc: one input, one output, continuous time only");
    endif
    B = m.B{1};
    F = m.F{1};
  elseif (isnumeric (M))
    if (isempty (rest) || ! isnumeric (rest{1}))
      error ("bandwidthc:badInput",
             "bandwidthc: give the model or both B and F");
    endif
    B = M;
    F = rest{1};
    rest = rest(2:end);
  else
    error ("bandwidthc:badInput",
           ["bandwidthc: the model must be an idpoly, idtf, idproc, ", ...
            "idctm, a struct with B and F, a tf, or B and F"]);
  endif
  if (iscell (B))
    if (numel (B) != 1)
      error ("bandwidthc:badInput",
             "bandwidthc: one input only (B has %d numerators)", numel (B));
    endif
    B = B{1};
  endif
  B = check_poly (B, "B");
  F = check_poly (F, "F");
  if (isempty (B))
    error ("bandwidthc:badInput", "bandwidthc: B must not be zero");
  endif
  if (isempty (F))
    error ("bandwidthc:badInput", "bandwidthc: F must not be zero");
  endif
  if (numel (B) > numel (F))
    error ("bandwidthc:badInput",
           "bandwidthc: improper model (deg B > deg F)");
  endif
endfunction

function c = check_poly (c, what)
  if (! isnumeric (c) || ! isreal (c) || ! isvector (c)
      || any (! isfinite (c)))
    error ("bandwidthc:badInput",
           "bandwidthc: %s must be a finite real coefficient vector", what);
  endif
  c = double (c(:).');
  k = find (c != 0, 1);
  c = c(k:end);
endfunction

%!test  # 2nd order: wn sqrt (1 - 2 z^2 + sqrt ((1 - 2 z^2)^2 + 1))
%! for zeta = [0.1 0.6 0.707 2]
%!   wn = 3;
%!   q = 1 - 2 * zeta ^ 2;
%!   [wb, kind, gref] = bandwidthc (7 * wn ^ 2, [1 2 * zeta * wn wn ^ 2]);
%!   assert (wb, wn * sqrt (q + sqrt (q ^ 2 + 1)), 1e-9 * wn);
%!   assert (kind, "lowpass");
%!   assert (gref, 7, 1e-12);
%! endfor

%!test  # first order and an idctm model; a struct
%! assert (bandwidthc (idctm (2, [1 5])), 5, 1e-9);
%! assert (bandwidthc (idproc ("P1", "Kp", 3, "Tp1", 0.2)), 5, 1e-9);
%! assert (bandwidthc (struct ("B", 2, "F", [1 5])), 5, 1e-9);

%!test  # band-pass b0 p / (p^2 + a1 p + a2): upper half-power frequency
%! a1 = 3; a2 = 100;
%! [wb, kind, gref] = bandwidthc ([5 0], [1 a1 a2]);
%! assert (wb, a1 / 2 + sqrt (a1 ^ 2 / 4 + a2), 1e-9 * wb);
%! assert (kind, "bandpass");
%! assert (gref, 5 / a1, 1e-9);              # peak at sqrt (a2)

%!test  # a zero near the origin counts as one at the origin below wmin
%! a1 = 3; a2 = 100;
%! wb0 = bandwidthc ([5 0], [1 a1 a2]);
%! wb = bandwidthc ([5 1e-4], [1 a1 a2], "wmin", 0.01);
%! assert (wb, wb0, 1e-9 * wb0);
%! [~, kind] = bandwidthc ([5 1e-4], [1 a1 a2], "wmin", 0);
%! assert (kind, "lowpass");

%!test  # integrator: bandwidth of the integrator-free part
%! [wb, kind] = bandwidthc (3, [1 4 0]);    # 3 / (p (p + 4))
%! assert (wb, 4, 1e-9);
%! assert (kind, "integrator");
%! [wb, kind] = bandwidthc (3, [1 0]);      # pure integrator
%! assert (isnan (wb));
%! assert (kind, "integrator-noedge");

%!test  # biproper models without roll-off: the largest corner frequency
%! [wb, kind] = bandwidthc ([1 0], [1 2]);  # p / (p + 2)
%! assert (wb, 2, 1e-12);
%! assert (kind, "bandpass-noedge");
%! [wb, kind] = bandwidthc ([1 1], [1 10]);  # (p + 1)/(p + 10): gain rises
%! assert (wb, 10, 1e-12);
%! assert (kind, "lowpass-noedge");
%! wb = bandwidthc ([1 10], [1 1]);   # (p + 10)/(p + 1): a lag, it falls
%! assert (wb, sqrt (50 / 49), 1e-9);

%!test  # lag network (p + 10)/((p + 1)(p + 100)): crossing after the dip
%! wb = bandwidthc ([1 10], conv ([1 1], [1 100]));
%! G = @(w) abs ((1i * w + 10) ./ ((1i * w + 1) .* (1i * w + 100)));
%! assert (G (wb), 0.1 / sqrt (2), 1e-9);
%! assert (all (G (wb * (1.01:0.5:100)) < 0.1 / sqrt (2)));

%!error id=bandwidthc:badInput bandwidthc ()
%!error id=bandwidthc:badInput bandwidthc (1)
%!error id=bandwidthc:badInput bandwidthc ("x")
%!error id=bandwidthc:badInput bandwidthc (struct ("B", 1))
%!error id=bandwidthc:badInput bandwidthc ({1, 2}, [1 1])
%!error id=bandwidthc:badInput bandwidthc ([1 2 3], [1 1])
%!error id=bandwidthc:badInput bandwidthc (0, [1 1])
%!error id=bandwidthc:badInput bandwidthc (1, 0)
%!error id=bandwidthc:badInput bandwidthc ([1 NaN], [1 1])
%!error id=bandwidthc:badInput bandwidthc (1, [1 1i])
%!error id=bandwidthc:badInput bandwidthc (1, [1 1], "wmin", -1)
%!error id=bandwidthc:badOption bandwidthc (1, [1 1], "w", 1)
%!error id=bandwidthc:badOption bandwidthc (1, [1 1], "wmin")

%!demo
%! ## Bandwidths of the frozen models of thesis example 2.3.5 (Fig. 1.7).
%! t = 0:250:9000;
%! wn = 2 * (1 + 0.3 * cos (2 * pi * t / 4500));
%! wb = arrayfun (@(w) bandwidthc (w ^ 2, [1 1.2 * w w ^ 2]), wn);
%! plot (t, wb, "o-"); xlabel ("t (s)"); ylabel ("\\omega_b (rad/s)");
%! printf ("bandwidth range [%.3f, %.3f] rad/s\n", min (wb), max (wb));

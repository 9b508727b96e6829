## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {[@var{H}, @var{w}, @var{sdmag}, @var{sdph}] =} freq_data (@var{sys}, @var{w}, @var{fname})
## Frequency response (ny-by-nu-by-N) of a model of this toolbox or the
## control package at @var{w} (default: two decades around its poles and
## zeros, or an idfrd's own frequencies), and, for a model with a
## covariance, the standard deviations of the magnitude and of the phase
## (degrees) by first-order propagation, J P J', with J the derivative of
## |H| and arg H with respect to the parameters (central differences).
## @end deftypefn

function [H, w, sdmag, sdph] = freq_data (sys, w, fname)
  if (isa (sys, "idmodel"))
    P = pstruct (sys);
    if (isempty (w))
      if (strcmp (P.kind, "idfrd"))
        w = P.par.Frequency;
      else
        if (strcmp (P.kind, "idss"))
          [num, den] = deal ({0}, {poly(P.par.A)});
        else
          [num, den] = tf_parts (P);
        endif
        w = default_w (num, den, P.Ts);
      endif
    endif
    H = freqresp (sys, w);
  else
    P = [];
    if (isempty (w))
      [num, den] = tfdata (sys);
      w = default_w (num, den, max (get (sys, "tsam"), 0));
    endif
    H = reshape (freqresp (sys, w), size (sys, 1), size (sys, 2), []);
  endif
  sdmag = [];
  sdph = [];
  if (nargout > 2 && ! isempty (P) && ! isempty (P.cov))
    p = getpvec (sys);
    np = numel (p);
    Jm = zeros (numel (H), np);
    Jp = zeros (numel (H), np);
    for k = find (diag (P.cov) > 0).'   # fixed ones (a delay) add nothing
      h = 1e-6 * max (abs (p(k)), 1);
      dp = zeros (np, 1);
      dp(k) = h;
      Hp = freqresp (setpvec (sys, p + dp), w);
      Hm = freqresp (setpvec (sys, p - dp), w);
      Jm(:, k) = (abs (Hp(:)) - abs (Hm(:))) / (2 * h);
      Jp(:, k) = angle (Hp(:) ./ Hm(:)) / (2 * h);
    endfor
    sdmag = reshape (sqrt (max (sum ((Jm * P.cov) .* Jm, 2), 0)), size (H));
    sdph = 180 / pi * reshape (sqrt (max (sum ((Jp * P.cov) .* Jp, 2), 0)),
                               size (H));
  endif
endfunction

function w = default_w (num, den, Ts)
  r = [];
  for k = 1:numel (num)
    r = [r; abs(roots (num{k})); abs(roots (den{k}))];
  endfor
  if (Ts > 0)
    r = abs (log (r(r > 0))) / Ts;
  endif
  r = r(r > 1e-12 & isfinite (r));
  if (isempty (r))
    r = 1;
  endif
  lo = floor (log10 (min (r))) - 1;
  hi = ceil (log10 (max (r))) + 1;
  if (Ts > 0)
    hi = min (hi, log10 (pi / Ts));
  endif
  w = logspace (lo, hi, 300)';
endfunction

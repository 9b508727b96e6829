## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn  {} {} bode (@var{M})
## @deftypefnx {} {} bode (@var{M1}, @var{style1}, @var{M2}, @var{style2}, @dots{}, @var{w})
## @deftypefnx {} {} bode (@dots{}, "sd", @var{k})
## @deftypefnx {} {} bode (@dots{}, "sd", @var{k}, "fill")
## @deftypefnx {} {[@var{mag}, @var{phase}, @var{w}] =} bode (@var{M}, @var{w})
## @deftypefnx {} {[@var{mag}, @var{phase}, @var{w}, @var{sdmag}, @var{sdphase}] =} bode (@var{M}, @var{w})
## Bode diagram of models (this toolbox's; control-package models may be
## mixed in), delays included.  @var{w}: frequencies (rad/s) or
## @{wmin, wmax@}.  With @code{"sd", k} a model that has a covariance
## (an estimate) is drawn with its band of +- k standard deviations,
## dashed or, with @code{"fill"}, shaded; the standard deviations come from
## the parameter covariance by first-order propagation.  Outputs as in
## MATLAB: @var{mag} (absolute value) and @var{phase} (degrees) are
## ny-by-nu-by-N; the frequency response itself comes from the control
## package's @code{freqresp} on @code{tf (M)}.
## @end deftypefn

function varargout = bode (varargin)
  varargout = contsid_guard ({"bode", "idmodel"}, @bode_body, nargout,
                             varargin);
endfunction

function [mag, phase, wout, sdmag, sdphase, varargout] = bode_body (varargin)
  contsid_nargchk ("bode", nargin, nargout, [1 Inf], 5);
  [sys, styles, w, opt] = parse_sys_args ("bode", varargin);
  if (nargout > 0)
    [H, wout, sdm, sdp] = freq_data (sys{1}, w, "bode");
    mag = abs (H);
    phase = unwrap_deg (H);
    sdmag = sdm;
    sdphase = sdp;
    return;
  endif
  for s = 1:numel (sys)
    [H, ws, sdm, sdp] = freq_data (sys{s}, w, "bode");
    if (isempty (w))
      w = ws;                          # the first model sets the grid
    endif
    st = styles{s};
    if (isempty (st))
      st = "-";
    endif
    m = abs (H);
    ph = unwrap_deg (H);
    for i = 1:size (H, 1)
      for j = 1:size (H, 2)
        mij = squeeze (m(i, j, :));
        pij = squeeze (ph(i, j, :));
        subplot (2, 1, 1);
        hold on;
        semilogx (ws, 20 * log10 (mij), st);
        if (opt.sd > 0 && ! isempty (sdm))
          lo = max (mij - opt.sd * squeeze (sdm(i, j, :)), mij * 1e-6);
          hi = mij + opt.sd * squeeze (sdm(i, j, :));
          band (ws, 20 * log10 (lo), 20 * log10 (hi), opt.fill);
        endif
        set (gca, "xscale", "log");
        ylabel ("magnitude (dB)");
        grid on;
        subplot (2, 1, 2);
        hold on;
        semilogx (ws, pij, st);
        if (opt.sd > 0 && ! isempty (sdp))
          d = opt.sd * squeeze (sdp(i, j, :));
          band (ws, pij - d, pij + d, opt.fill);
        endif
        set (gca, "xscale", "log");
        ylabel ("phase (deg)");
        xlabel ("frequency (rad/s)");
        grid on;
      endfor
    endfor
  endfor
  subplot (2, 1, 1); hold off;
  subplot (2, 1, 2); hold off;
endfunction

function ph = unwrap_deg (H)
  ph = zeros (size (H));
  for i = 1:size (H, 1)
    for j = 1:size (H, 2)
      ph(i, j, :) = unwrap (angle (squeeze (H(i, j, :)))) * 180 / pi;
    endfor
  endfor
endfunction

function band (w, lo, hi, filled)
  if (filled)
    fill ([w; flipud(w)], [lo; flipud(hi)], [0.8 0.8 0.8],
          "edgecolor", "none", "facealpha", 0.5);
  else
    semilogx (w, lo, "k:", w, hi, "k:");
  endif
endfunction

%!test  # magnitude and phase equal the control package's bode of tf (M)
%! pkg load control
%! w = logspace (-1, 2, 30)';
%! M = idpoly (1, [1 4], 1, 1, [1 2.4 4], "Ts", 0);
%! [m, p, wo] = bode (M, w);
%! [mc, pc] = bode (tf ([1 4], [1 2.4 4]), w);
%! assert (size (m), [1 1 30]);
%! assert (squeeze (m), mc(:), 1e-12);
%! assert (squeeze (p), pc(:), 1e-9);
%! ## the delay adds -w tau to the phase only
%! [md, pd] = bode (idtf ([1 4], [1 2.4 4], "IODelay", 0.1), w);
%! assert (squeeze (md), mc(:), 1e-12);
%! assert (squeeze (pd), pc(:) - w * 0.1 * 180 / pi, 1e-9);

%!test  # 'sd': first-order propagation, checked on |b/(s + a)|
%! C = [0.01 0.002; 0.002 0.04];          # cov of [b a] (getpvec order)
%! M = setcov (idtf (2, [1 3]), C);
%! w = [0.5; 2];
%! [m, p, ~, sdm] = bode (M, w);
%! J = [1 ./ abs(1i*w + 3), -2 * 3 ./ abs(1i*w + 3) .^ 3];
%! assert (squeeze (sdm), sqrt (sum ((J * C) .* J, 2)), 1e-6);

%!test  # plots, with bands, several models and styles
%! M = setcov (idtf (2, [1 3]), diag ([0.01 0.04]));
%! h = figure ("visible", "off");
%! bode (M, "b-", idtf (2.2, [1 3.1]), "r--", "sd", 3, "fill");
%! bode (idfrd (idtf (2, [1 3]), logspace (-1, 1, 20)));
%! close (h);

%!error id=bode:badInput bode (idtf (1, [1 1]), realmax)
%!error id=bode:badInput bode (idtf (1, [1 1]), "sd")
%!error id=bode:badInput bode (idtf (1, [1 1]), {1})
%!error id=bode:badInput bode (idtf (1, [1 1]), struct ())

%!demo
%! M0 = idpoly (1, 4, 1, 1, [1 2.4 4], "Ts", 0);
%! M = setcov (M0, 0.01 * eye (3));
%! bode (M0, "b-", M, "r--", "sd", 3, "fill");

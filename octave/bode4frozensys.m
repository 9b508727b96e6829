## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn  {} {} bode4frozensys (@var{THM}, @var{nn})
## @deftypefnx {} {} bode4frozensys (@var{THM}, @var{nn}, "w", @var{w}, @dots{})
## @deftypefnx {} {[@var{mag}, @var{phase}, @var{w}] =} bode4frozensys (@dots{})
## @deftypefnx {} {} bode4frozensys (@var{M}, @dots{})
## Bode diagrams of the frozen (time-instant) models of a recursive
## estimate: row k of @var{THM} taken as the LTI model of sample k.
##
## @var{nn} = [na nb] (or [na nb nk]) with @var{THM} ordered
## [a1 .. a_na, b0 .. b_(nb-1)] as returned by @code{rlssvf} and
## @code{rivsvf}. For @code{rsrivc}'s [b f] order give
## @code{"order", "bf"} and @var{nn} = [nb nf].
##
## A model @var{M} (an @code{idpoly} from @code{srivc}, ..., an
## @code{idtf}, @code{idproc}, @code{idctm}, or a struct with B and F) is
## shown as its one frozen model.
##
## Options: @code{"w"} frequencies in rad/s (default 100 points, log-spaced
## around the models' corner frequencies); @code{"samples"} the rows of
## @var{THM} to use (default 10 rows evenly spaced over the record);
## @code{"order"} @qcode{"ab"} (default) or @qcode{"bf"}.
##
## Without outputs it plots magnitude (dB) and phase (degrees) of the
## selected frozen models; with outputs it returns @var{mag} and @var{phase}
## (numel(w)-by-numel(samples)) and @var{w} instead.
##
## @strong{Example}
## @example
## THM = [linspace(2, 3, 50)', 4 * ones(50, 1), 4 * ones(50, 1)];
## [mag, ph, w] = bode4frozensys (THM, [2 1], "w", logspace (-1, 1, 20));
## @end example
## @seealso{rlssvf, rivsvf, rsrivc}
## @end deftypefn

function varargout = bode4frozensys (varargin)
  varargout = contsid_guard ("bode4frozensys", @bode4frozensys_body, nargout,
                             varargin);
endfunction

function [mag, phase, w, varargout] = bode4frozensys_body (THM, nn, varargin)
  contsid_nargchk ("bode4frozensys", nargin, nargout, [2 Inf], 3);
  fname = "bode4frozensys";
  if (nargin >= 1 && (isobject (THM) || isstruct (THM)))
    ## An offline model: its single (time-invariant) frozen model.
    m = contsid_model (fname, THM);
    if (! strcmp (m.kind, "tf") || m.nu != 1 || m.ny != 1 || m.Ts > 0)
      error ("bode4frozensys:badInput",
             ["bode4frozensys: only continuous-time models with one ", ...
              "input and one output"]);
    endif
    m.B = m.B{1};
    m.F = m.F{1};
    args = {};
    if (nargin >= 2)
      args = [{nn}, varargin];
    endif
    theta = [m.F(2:end), m.B];
    nn = [numel(m.F) - 1, numel(m.B)];
    if (nargout == 0)
      bode4frozensys (theta, nn, args{:});
    else
      [mag, phase, w] = bode4frozensys (theta, nn, args{:});
    endif
    return;
  endif
  if (nargin < 2)
    error ("bode4frozensys:badInput", "bode4frozensys: expected THM and nn");
  endif
  if (! isnumeric (THM) || ! isreal (THM) || ndims (THM) != 2 || isempty (THM)
      || any (! isfinite (THM(:))))
    error ("bode4frozensys:badInput",
           "bode4frozensys: THM must be a finite real matrix");
  endif
  if (! isnumeric (nn) || ! isreal (nn) || numel (nn) < 2 || numel (nn) > 3
      || any (nn != fix (nn)) || any (nn(1:2) < 1))
    error ("bode4frozensys:badInput", "bode4frozensys: nn must be [na nb]");
  endif
  opts = contsid_options (fname, struct ("w", [], "samples", [],
                                        "order", "ab"), varargin);
  if (! ischar (opts.order) || ! any (strcmpi (opts.order, {"ab", "bf"})))
    error ("bode4frozensys:badOption", ...
           "bode4frozensys: order must be 'ab' or 'bf'");
  endif
  if (strcmpi (opts.order, "bf"))
    nb = nn(1); na = nn(2);
  else
    na = nn(1); nb = nn(2);
  endif
  if (columns (THM) != na + nb)
    error ("bode4frozensys:dimensionMismatch",
           "bode4frozensys: THM must have %d columns (na + nb)", na + nb);
  endif
  if (strcmpi (opts.order, "bf"))
    THM = THM(:, [nb+1:end, 1:nb]);
  endif
  N = rows (THM);
  k = opts.samples;
  if (isempty (k))
    k = unique (round (linspace (1, N, min (N, 10))));
  elseif (! isnumeric (k) || any (k != fix (k)) || any (k < 1) || any (k > N))
    error ("bode4frozensys:badInput",
           "bode4frozensys: samples must be row indices of THM");
  endif
  w = opts.w;
  if (isempty (w))
    corners = abs (THM(k, na)) .^ (1 / na);
    corners = corners(corners > 0);
    if (isempty (corners))
      corners = 1;
    endif
    w = logspace (log10 (min (corners)) - 2, log10 (max (corners)) + 2, 100);
  elseif (! isnumeric (w) || ! isreal (w) || any (w < 0)
          || any (! isfinite (w)))
    error ("bode4frozensys:badInput",
           "bode4frozensys: w must be finite frequencies >= 0 (rad/s)");
  endif
  w = w(:);
  s = 1i * w;
  G = zeros (numel (w), numel (k));
  for c = 1:numel (k)
    th = THM(k(c), :);
    G(:, c) = polyval (th(na+1:end), s) ./ polyval ([1 th(1:na)], s);
  endfor
  m = 20 * log10 (abs (G));
  p = unwrap (angle (G)) * 180 / pi;
  if (nargout > 0)
    mag = m;
    phase = p;
    return;
  endif
  subplot (2, 1, 1);
  semilogx (w, m);
  ylabel ("magnitude (dB)");
  grid on;
  title ("Bode diagrams of the frozen models");
  subplot (2, 1, 2);
  semilogx (w, p);
  ylabel ("phase (deg)");
  xlabel ("frequency (rad/s)");
  grid on;
endfunction

%!test  # agrees with the analytic frequency response
%! THM = [2.4 4 4; 1 9 9];
%! w = [0.1 1 3];
%! [mag, ph] = bode4frozensys (THM, [2 1], "w", w, "samples", [1 2]);
%! G = 4 ./ ((1i * w) .^ 2 + 2.4 * 1i * w + 4);
%! assert (mag(:, 1), 20 * log10 (abs (G(:))), 1e-12);
%! assert (ph(:, 1), unwrap (angle (G(:))) * 180 / pi, 1e-10);

%!test  # rsrivc order [b f]
%! [m1] = bode4frozensys ([2.4 4 4], [2 1], "w", [1 2]);
%! [m2] = bode4frozensys ([4 2.4 4], [1 2], "w", [1 2], "order", "bf");
%! assert (m1, m2, 1e-12);

%!test  # an idctm model
%! [m1] = bode4frozensys ([2.4 4 4], [2 1], "w", [1 2]);
%! [m2] = bode4frozensys (idctm (4, [1 2.4 4]), "w", [1 2]);
%! assert (m1, m2, 1e-12);
%! [m3] = bode4frozensys (idtf (4, [1 2.4 4]), "w", [1 2]);
%! assert (m3, m1, 1e-12);
%!error id=bode4frozensys:badInput bode4frozensys (idss (-1, [1 1], 1, [0 0]))

%!error id=bode4frozensys:badInput bode4frozensys ([1 2 3])
%!error id=bode4frozensys:badInput bode4frozensys ([1 NaN 3], [2 1])
%!error id=bode4frozensys:badInput bode4frozensys ([1 2 3], [0 1])
%!error id=bode4frozensys:dimensionMismatch bode4frozensys ([1 2 3 4], [2 1])
%!error id=bode4frozensys:badInput bode4frozensys ([1 2 3], [2 1], "w", -1)
%!error id=bode4frozensys:badInput bode4frozensys ([1 2 3], [2 1], "samples", 5)
%!error id=bode4frozensys:badOption bode4frozensys ([1 2 3], [2 1], "order", "x")
%!error id=bode4frozensys:badOption bode4frozensys ([1 2 3], [2 1], "bogus", 1)

%!demo
%! t = (0:999)';
%! wn = 2 * (1 + 0.3 * cos (2 * pi * t / 1000));
%! THM = [1.2 * wn, wn .^ 2, wn .^ 2];
%! bode4frozensys (THM, [2 1], "w", logspace (-1, 1.5, 200));

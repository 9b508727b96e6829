## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn  {} {} zpplot (@var{M1}, @var{M2}, @dots{})
## @deftypefnx {} {} zpplot (@dots{}, "sd", @var{k})
## The System Identification Toolbox's pole-zero plot: as @code{pzmap};
## with @code{"sd", k} and a covariance, each pole and zero gets a circle
## of radius k times its standard deviation (first-order propagation of
## the parameter covariance).
## @end deftypefn

function varargout = zpplot (varargin)
  varargout = contsid_guard ({"zpplot", "idmodel"}, @zpplot_body, nargout,
                             varargin);
endfunction

function varargout = zpplot_body (varargin)
  contsid_nargchk ("zpplot", nargin, nargout, [1 Inf], 0);
  [sys, styles, ~, opt] = parse_sys_args ("zpplot", varargin);
  args = [sys; styles];
  pzmap (args{:});
  if (opt.sd == 0)
    return;
  endif
  hold on;
  th = linspace (0, 2 * pi, 60);
  for s = 1:numel (sys)
    if (! isa (sys{s}, "idmodel") || isempty (getcov (sys{s})))
      continue;
    endif
    [r, sd] = root_sd (sys{s});
    for i = 1:numel (r)
      plot (real (r(i)) + opt.sd * sd(i) * cos (th),
            imag (r(i)) + opt.sd * sd(i) * sin (th), "k:");
    endfor
  endfor
  hold off;
endfunction

function [r, sd] = root_sd (M)
  p = getpvec (M);
  C = getcov (M);
  r = [pole(M); zero(M)];
  J = zeros (numel (r), numel (p));
  for k = find (diag (C) > 0).'   # fixed parameters (a delay) add nothing
    h = 1e-6 * max (abs (p(k)), 1);
    dp = zeros (size (p));
    dp(k) = h;
    Mp = setpvec (M, p + dp);
    rp = [pole(Mp); zero(Mp)];
    ## match the perturbed roots to the nominal ones (nearest)
    for i = 1:numel (r)
      [~, j] = min (abs (rp - r(i)));
      J(i, k) = abs (rp(j) - r(i)) / h;
    endfor
  endfor
  sd = sqrt (max (sum ((J * C) .* J, 2), 0));
endfunction

%!test
%! h = figure ("visible", "off");
%! M = setcov (idtf (2, [1 3]), diag ([0.01 0.04]));
%! zpplot (M, "sd", 3);
%! close (h);
%! [~, sd] = getpvec (M);
%! assert (sd(2), 0.2, 1e-15);   # the pole -a moves with a: sd 0.2
%!error id=zpplot:badInput zpplot (idtf (1, [1 1]), "sd", 0)

%!demo
%! M = setcov (idtf (2, [1 3 2]), 0.01 * eye (3));
%! zpplot (M, "sd", 3);

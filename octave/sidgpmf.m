## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn  {} {@var{M} =} sidgpmf (@var{data}, @var{i}, @var{j}, @var{lambda})
## @deftypefnx {} {@var{M} =} sidgpmf (@var{data}, @var{i}, @var{j}, @var{lambda}, @var{n})
## @deftypefnx {} {@var{M} =} sidgpmf (@var{data}, @var{i}, @var{j}, @var{lambda}, @var{n}, @var{n0})
## @deftypefnx {} {[@var{M}, @var{sv}] =} sidgpmf (@dots{})
## Subspace (4SID) estimate of a multivariable continuous-time state-space
## model from generalised Poisson moment functionals (GPMF).
##
## @var{data} is an @code{iddata} object with @var{p} outputs and @var{m}
## inputs (regular or irregular sampling, InterSample @qcode{"zoh"} or
## @qcode{"foh"}, one rule for all inputs).  @var{i} (>= 2) is the number
## of time derivatives used, 0 .. @var{i}-1; @var{j} (>= @var{i} - 1,
## @var{j} >= @var{i} advised) the order of the GPMF, i.e. of the Poisson
## filter @code{(lambda/(p + lambda))^(j+1)}; @var{lambda} its pole
## (rad/s).  @var{n} is the model order, 1 .. (@var{i}-1) @var{p}; empty
## or absent, it is chosen at the largest ratio of consecutive singular
## values @var{sv} of the projected data (returned as the second output).
## The regression uses the samples from @var{n0} on (default 1).
##
## Algorithm (Bastogne, Garnier and Sibille, Int. J. Control 74(2),
## 2001): the GPMF of the derivatives of y and u obey the data equation of
## discrete 4SID methods with derivatives in place of time shifts,
## @code{Y = Gamma X + H U}, @code{Gamma = [C; C A; ...; C A^(i-1)]}.  The
## MOESP projection of @var{Y} onto the complement of @var{U} gives the
## column space of @var{Gamma}, hence @var{C} (first block) and @var{A}
## (shift invariance).  @var{B} and @var{D} are then fitted by least
## squares to the measured outputs, through the exact simulation of
## @code{(A, I, C)} for each input.  With output noise the basic
## projection is biased: a starting point for @code{ssivgpmf} or a
## refined method at high noise levels.
##
## @var{M} is a continuous-time @code{idss} (@var{Ts} = 0); its state basis
## is that of the SVD, so compare models by their frequency responses or
## transfer functions.
##
## @strong{Example}
## @example
## A0 = [0 1 0; -3 -2 -1; -1 -2 -1];  B0 = [1 1; 2 1; 1 2];
## C0 = [1 0 0; 0 0 1];
## Ts = 0.01;  u = kron (sign (randn (200, 2)), ones (50, 1));
## y = lsim (c2d (ss (A0, B0, C0, zeros (2)), Ts), u);
## M = sidgpmf (iddata (y, u, Ts), 3, 3, 3, 3);
## eig (M.A)
## @end example
## @seealso{sslsgpmf, ssivgpmf, idss}
## @end deftypefn

function varargout = sidgpmf (varargin)
  varargout = contsid_guard ("sidgpmf", @sidgpmf_body, nargout, varargin);
endfunction

function [M, sv, varargout] = sidgpmf_body (varargin)
  contsid_nargchk ("sidgpmf", nargin, nargout, [4 6], 2);
  [M, sv] = contsid_gpmf ("sidgpmf", varargin);
endfunction

%!function H = gpmf_freq (A, B, C, D, w)
%!  H = zeros (rows (C), columns (B), numel (w));
%!  for k = 1:numel (w)
%!    H(:,:,k) = C * ((1i * w(k) * eye (rows (A)) - A) \ B) + D;
%!  endfor
%!endfunction

## The system of the sslsgpmf tests.
%!shared A0, B0, C0, u, Ts, w, y, H0
%! pkg load control;
%! A0 = [-1 1 0; -1 -1 0; 0 0 -2];
%! B0 = [1 0; 0 1; 1 1];
%! C0 = [1 0 1; 0 1 0];
%! Ts = 0.01;
%! state = rand ("state");
%! rand ("state", 7);
%! u = kron (sign (rand (120, 2) - 0.5), ones (50, 1));
%! rand ("state", state);
%! w = logspace (-1, 1, 20);
%! y = lsim (c2d (ss (A0, B0, C0, zeros (2)), Ts, "zoh"), u);
%! H0 = gpmf_freq (A0, B0, C0, zeros (2), w);

## Noise-free data: the frequency response and the poles are the true ones
## up to the O((lambda Ts)^2) filtering error of y; without n the order is
## found at the gap of the singular values.
%!test
%! [M, sv] = sidgpmf (iddata (y, u, Ts), 3, 3, 3, 3);
%! assert (isa (M, "idss"));
%! assert (M.Ts, 0);
%! assert (size (M.A), [3 3]);
%! H = gpmf_freq (M.A, M.B, M.C, M.D, w);
%! assert (max (abs (H(:) - H0(:))) / max (abs (H0(:))) < 1e-3);
%! assert (numel (sv), 6);
%! M2 = sidgpmf (iddata (y, u, Ts), 3, 3, 3);
%! assert (size (M2.A), [3 3]);

## Irregular sampling (samples dropped at random, never where u steps).
%!test
%! t = (0:5999)' * Ts;
%! state = rand ("state");
%! rand ("state", 3);
%! keep = find (rand (6000, 1) > 0.3 | mod ((0:5999)', 50) == 0);
%! rand ("state", state);
%! M = sidgpmf (iddata (y(keep,:), u(keep,:), "SamplingInstants", t(keep)),
%!              3, 3, 3, 3);
%! H = gpmf_freq (M.A, M.B, M.C, M.D, w);
%! assert (max (abs (H(:) - H0(:))) / max (abs (H0(:))) < 1e-3);

%!error <at least 4> sidgpmf (iddata ((1:10)', (1:10)', 1), 3, 3)
%!error id=sidgpmf:badInput sidgpmf ((1:10)', 3, 3, 3)
%!error id=sidgpmf:badInput ...
%! sidgpmf (iddata (rand (500, 2), rand (500, 2), 1), 1, 3, 3)
%!error id=sidgpmf:badInput ...
%! sidgpmf (iddata (rand (500, 2), rand (500, 2), 1), 3, 1, 3)
%!error id=sidgpmf:badInput ...
%! sidgpmf (iddata (rand (500, 2), rand (500, 2), 1), 3, 3, [3 3])
%!error id=sidgpmf:badInput ...
%! sidgpmf (iddata (rand (500, 2), rand (500, 2), 1), 3, 3, -3)
%!error id=sidgpmf:badInput ...
%! sidgpmf (iddata (rand (500, 2), rand (500, 2), 1), 3, 3, 3, 5)
%!error id=sidgpmf:badInput ...
%! sidgpmf (iddata (rand (500, 2), rand (500, 2), 1), 3, 3, 3, 2, 0)
%!error id=sidgpmf:badInput ...
%! sidgpmf (iddata (rand (20, 2), rand (20, 2), 1), 3, 3, 3, 2)
%!error id=sidgpmf:numericalFailure ...
%! sidgpmf (iddata (rand (500, 2), zeros (500, 2), 1), 3, 3, 3, 2)

%!demo
%! pkg load control;
%! A0 = [0 1 0; -3 -2 -1; -1 -2 -1];  B0 = [1 1; 2 1; 1 2];
%! C0 = [1 0 0; 0 0 1];  Ts = 0.01;
%! u = kron (sign (randn (200, 2)), ones (50, 1));
%! y = lsim (c2d (ss (A0, B0, C0, zeros (2)), Ts), u);
%! y = y + 0.1 * std (y) .* randn (size (y));
%! [M, sv] = sidgpmf (iddata (y, u, Ts), 3, 3, 3);
%! disp (sv'); disp ([eig(M.A), eig(A0)]);

## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{R} =} hammerstein_mc (@var{runs})
## Monte Carlo check of the standard deviations reported by @code{hsrivc},
## @code{hrivc} and @code{hwsrivc} (target: the spread of the
## estimates over @var{runs} noise realisations divided by the mean
## reported sd lies in 0.8-1.25). Systems: CONTSID's Hammerstein demo
## (ubar = u + 0.5 u^2 + 0.25 u^3, G = (10 s + 30)/(s^2 + s + 5), Ts =
## 0.5, N = 2000, uniform input, white noise at SNR 10 dB; for hrivc the
## noise (1 + 0.5 q^-1)/(1 - 0.85 q^-1) e), and its Hammerstein-Wiener
## demo (f = u - 2u^2 + 0.8u^3, G = 1/(s + 2), g = x + 1.5x^2 + x^3,
## Ts = 5 ms, N = 5000, noise sd 0.03). The input is the same in every run,
## the noise changes. Prints and returns the ratio per parameter.
## @example
## devel/run-study hammerstein_mc 100
## @end example
## @end deftypefn

function R = hammerstein_mc (runs)
  if (nargin < 1)
    runs = 100;
  endif
  warning ("off", "all");
  rand ("state", 1);
  N = 2000; Ts = 0.5;
  u = 4 * rand (N, 1) - 2;
  W = [u u.^2 u.^3];
  ydet = simc (idpoly (1, [10 30], 1, 1, [1 1 5], 0, 0),
               iddata ([], W * [1; 0.5; 0.25], Ts));
  truth = [1 5 10 30 0.5 0.25]';
  sig = sqrt (var (ydet) / 10);
  R = struct ();
  R.hsrivc = run_mc ("hsrivc", runs, truth, @(k) hsrivc (
    iddata (ydet + sig * randn (N, 1), W, Ts), [2 2 0]));
  arma = @() filter ([1 0.5], [1 -0.85], 0.5 * sig * randn (N, 1));
  R.hrivc = run_mc ("hrivc", runs, truth, @(k) hrivc (
    iddata (ydet + arma (), W, Ts), [2 1 1 2 0]));
  Ts2 = 5e-3; N2 = 5000;
  u2 = 0.5 * kron (2 * rand (13, 1) - 1, ones (400, 1));
  u2 = u2(1:N2);
  xbar = simc (idpoly (1, 1, 1, 1, [1 2], 0, 0),
               iddata ([], u2 - 2 * u2.^2 + 0.8 * u2.^3, Ts2));
  x = xbar;
  for k = 1:60
    x -= (x + 1.5 * x.^2 + x.^3 - xbar) ./ (1 + 3 * x + 3 * x.^2);
  endfor
  R.hwsrivc = run_mc ("hwsrivc", max (20, round (runs / 2)),
                      [2 1 -2 0.8 1.5 1]', @(k) hwsrivc_infos (
                        iddata (x + 0.03 * randn (N2, 1), u2, Ts2)));
endfunction

function [M, I] = hwsrivc_infos (data)
  [M, I] = hwsrivc (data, [1 2 0 3 3]);
endfunction

function r = run_mc (name, runs, truth, fun)
  th = zeros (numel (truth), runs);
  sd = th;
  t_run = tic ();
  for k = 1:runs
    randn ("state", 100 + k);
    [~, I] = fun (k);
    th(:, k) = I.theta;
    sd(:, k) = I.sd(:);
  endfor
  t = toc (t_run);
  r.ratio = (std (th, 0, 2) ./ mean (sd, 2)).';
  r.bias_in_sd = ((mean (th, 2) - truth) ./ std (th, 0, 2)).';
  r.seconds = t;
  printf ("%s, %d runs (%.0f s): spread / reported sd = %s\n", name, runs, t,
          mat2str (r.ratio, 3));
  printf ("  bias / spread = %s\n", mat2str (r.bias_in_sd, 2));
endfunction

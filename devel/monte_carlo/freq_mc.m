## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{R} =} freq_mc (@var{runs})
## Monte Carlo check of the standard deviations reported by the
## frequency-domain estimators (target: spread / mean reported sd in
## 0.8-1.25): @code{srivc} on an @code{idfrd} of G = (2 s + 6)/(s^2 +
## 1.5 s + 9), and @code{tffsrivc}, @code{tffcoe} (delay estimated) on
## G = (0.5 s + 4)/(s^2 + 1.2 s + 4) e^(-0.37 s), 50 frequencies
## log-spaced in [0.1, 31.6] rad/s, circular complex white noise of
## standard deviation 0.05 on G; @code{oe} and @code{tfest}
## (frequency-domain output error) on the first system's idfrd, and
## @code{oe} on frequency-domain iddata (the DFT of a multisine through
## the first system, noise on Y). Prints and returns the ratio per
## parameter ([b; a], then td), and the ratio of the robust spread
## (1.4826 median absolute deviation).
## @example
## devel/run-study freq_mc 200
## @end example
## @end deftypefn

function R = freq_mc (runs)
  if (nargin < 1)
    runs = 200;
  endif
  warning ("off", "all");
  mc = @mc_sd_ratio;                    # devel/monte_carlo/mc_sd_ratio.m
  w = logspace (-1, 1.5, 50).';
  s = 1i * w;
  G1 = (2 * s + 6) ./ (s.^2 + 1.5 * s + 9);
  G2 = (0.5 * s + 4) ./ (s.^2 + 1.2 * s + 4) .* exp (-0.37 * s);
  noise = @() 0.05 * (randn (50, 1) + 1i * randn (50, 1)) / sqrt (2);
  frd = @(G) idfrd (G + noise (), w, "Ts", 0);
  R.srivc = mc ("srivc (idfrd)", runs, @() srivc_th (frd (G1)));
  R.tffsrivc = mc ("tffsrivc (idfrd)", runs, @() tf_th (@tffsrivc, frd (G2)));
  R.tffcoe = mc ("tffcoe (idfrd)", runs, @() tf_th (@tffcoe, frd (G2)));
  R.oe = mc ("oe (idfrd)", runs, @() oe_th (frd (G1)));
  R.tfest = mc ("tfest (idfrd)", runs, @() tfest_th (frd (G1)));
  ## oe on frequency-domain iddata [Y U] (advantages52's construction:
  ## the DFT of a multisine, noise on Y only)
  ui = idinput (400, "sine", [0 0.5]);
  U = fft (iddata ([], ui, 0.05, "InterSample", "bl"));
  U.Ts = 0;
  Y0 = sim (idpoly (1, [2 6], 1, 1, [1 1.5 9], "Ts", 0), U);
  K = rows (Y0.y);
  noisy = @() Y0.y + 0.1 * (randn (K, 1) + 1i * randn (K, 1));
  fd = @() [setfield(Y0, "y", noisy ()) U];
  R.oe_iddata = mc ("oe (frequency iddata)", runs, @() oe_th (fd ()));
endfunction

function [th, sd] = srivc_th (G)
  M = srivc (G, [2 2]);
  th = M.theta(:);
  sd = sqrt (diag (M.covariance));
endfunction

function [th, sd] = tf_th (f, G)
  M = f (G, 2, 1);
  [th, sd] = getpvec (M);               # [b; a; IODelay] with its sd
endfunction

## oe and tfest (frequency-domain output error) on the same data
function [th, sd] = oe_th (G)
  [th, sd] = getpvec (oe (G, [2 2]));
endfunction

function [th, sd] = tfest_th (G)
  [th, sd] = getpvec (tfest (G, 2, 1));
  [th, sd] = deal (th(1:end-1), sd(1:end-1));   # the IODelay is fixed at 0
endfunction

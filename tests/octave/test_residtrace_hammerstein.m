## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {} test_residtrace_hammerstein ()
## residtrace's static-nonlinearity candidate fits the polynomial of the
## input of a plain model with nb >= 2 as a Hammerstein model through
## hsrivc. On CONTSID's Hammerstein demo system
## (ubar = u + 0.5 u^2 + 0.25 u^3, G = (10 s + 30)/(s^2 + s + 5)), noise
## at 10 dB SNR, the linear model given (SRIVC [2 2 0]):
## @itemize
## @item the effect is static_nonlinearity, the Hammerstein variant;
## @item its coefficients a2, a3 lie within 4 of their reported standard
## deviations of the truth;
## @item the model's channels are the products a_k B (u^2 and u^3 have
## the numerator of u times a2 and a3);
## @item its validation output is closer to the noise-free output than
## the unconstrained channels u, u^2, u^3 over F (srivc with three
## inputs) and than the linear model.
## @end itemize
## @end deftypefn

function test_residtrace_hammerstein ()
  randn ("state", 11); rand ("state", 11);
  N = 1500; Ts = 0.5;
  G = idpoly (1, [10 30], 1, 1, [1 1 5], 0, 0);
  f = @(u) u + 0.5 * u .^ 2 + 0.25 * u .^ 3;
  u = 4 * rand (N, 1) - 2; uv = 4 * rand (N, 1) - 2;
  y0 = simc (G, iddata ([], f (u), Ts));
  yv0 = simc (G, iddata ([], f (uv), Ts));
  s = std (y0) / sqrt (10);
  y = y0 + s * randn (N, 1);
  yv = yv0 + s * randn (N, 1);
  M = srivc (iddata (y, u, Ts), [2 2 0]);
  R = residtrace (iddata (y, u, Ts), M, "validation", iddata (yv, uv, Ts),
                  "effects", {"static_nonlinearity"}, "iterate", 1,
                  "levels", "none");
  printf ("effect %s (%s): %s\n", R.effect, R.ranking(1).variant,
          R.evidence.text);
  assert (R.effect, "static_nonlinearity");
  assert (! isempty (strfind (R.ranking(1).variant, "hsrivc")));
  a = R.evidence.value; sd = R.evidence.std;
  assert (all (abs (a - [0.5 0.25]) < 4 * sd),
          sprintf ("a = %s +- %s", mat2str (a, 4), mat2str (sd, 2)));
  ch = R.model.channels;
  assert (numel (ch), 3);
  b = ch(1).B;
  assert (ch(2).B, a(1) * b, 1e-12 * norm (b));
  assert (ch(3).B, a(2) * b, 1e-12 * norm (b));
  ## against the noise-free validation output: Hammerstein (the candidate)
  ## vs the unconstrained MISO SRIVC and the linear model
  e_h = rms (yv0 - R.sim.after);
  Mm = srivc (iddata (y, [u u.^2 u.^3], Ts), [2 2 2 2 0 0 0]);
  e_m = rms (yv0 - simc (Mm, iddata ([], [uv uv.^2 uv.^3], Ts)));
  e_l = rms (yv0 - R.sim.before);
  printf (["RMSE to the noise-free output: hsrivc %.4g, MISO %.4g, ", ...
           "linear %.4g\n"],
          e_h, e_m, e_l);
  assert (e_h < e_m);
  assert (e_h < 0.5 * e_l);
endfunction

function r = rms (e)
  r = sqrt (mean (e .^ 2));
endfunction

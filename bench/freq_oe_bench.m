## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{S} =} freq_oe_bench (@var{K}, @var{R})
## Speed of the frequency-domain output error (@code{oe}/@code{tfest} on an
## @code{idfrd}, core @file{freq_srivc.hpp} + the Levenberg-Marquardt of
## @file{output_error.hpp}) against the same iteration in plain Octave,
## side by side in one run: G = (2 s + 6) / (s^2 + 1.5 s + 9) on @var{K}
## (default 10 000) log-spaced frequencies from 0.1 to 100 rad/s, complex
## noise of sd 0.05. Both start from the same model, the frequency-domain
## SRIVC estimate moved by 20 % (the core's own start is that SRIVC
## fixed point, a stationary point of the loss with white noise, from
## which there is nothing left to iterate). The core runs through its
## gateway (@code{freq_srivc_mex}, output_error, theta_init: the gateway
## runs the SRIVC iterations from theta_init and then the LM, which finds
## the SRIVC fixed point stationary; so the core's time is SRIVC's
## iterations from th0, the plain one LM's from th0, both ending at the
## same estimate); the plain
## Octave LM (@code{plain_lm} below) is what a competent user writes:
## complex arithmetic vectorised over the frequencies, the exact Jacobian
## (d/db_j = (jw)^j / F, d/df_i = -(jw)^i B / F^2) with real and imaginary
## parts stacked, column scaling, QR, damping raised by 10 until the loss
## falls, lowered by 10 after a step, stopped when the relative step and
## loss decrease are below 1e-10. Also end to end: @code{oe (Gfrd, [nb
## nf])} (SRIVC start included). CPU time, best of @var{R} (default 5).
## Run from the repository root:
## @example
## nice octave-cli -q --eval "addpath octave bench; freq_oe_bench"
## @end example
## @end deftypefn

function S = freq_oe_bench (K = 10000, R = 5)
  addpath (fullfile (fileparts (mfilename ("fullpath")), "..", "octave",
                     "private"));
  randn ("state", 11);
  w = logspace (-1, 2, K).';
  s = 1i * w;
  B0 = [2 6]; F0 = [1 1.5 9];
  G = polyval (B0, s) ./ polyval (F0, s) ...
      + 0.05 * (randn (K, 1) + 1i * randn (K, 1)) / sqrt (2);
  Gfrd = idfrd (G, w, "Ts", 0);
  nb = 2; nf = 2;
  ## the start: SRIVC's estimate, moved by 20 %
  [ths, ~, infos] = freq_srivc_mex ("oe", w, G, [],
                                    struct ("na", nf, "nb", nb));
  th0 = 1.2 * ths(:);
  o = struct ("na", nf, "nb", nb, "output_error", true, "theta_init",
              th0.', "tol", 1e-10, "maxiter", 100);

  [thc, ~, ic] = freq_srivc_mex ("oe", w, G, [], o);
  tc = best_cpu (@() freq_srivc_mex ("oe", w, G, [], o), R);
  [thp, itp] = plain_lm (w, G, nf, nb, th0);
  tp = best_cpu (@() plain_lm (w, G, nf, nb, th0), R);
  Mo = oe (Gfrd, [nb nf]);
  to = best_cpu (@() oe (Gfrd, [nb nf]), R);
  tho = [Mo.F(2:end), Mo.B].';
  loss = @(th) sum (abs (G - polyval (th(nf+1:end), s)
                         ./ polyval ([1; th(1:nf)], s)) .^ 2) / K;
  S = struct ("K", K, "core_cpu", tc, "core_iterations", ic.iterations,
              "plain_cpu", tp, "plain_iterations", itp, "ratio", tp / tc,
              "oe_cpu", to, "theta_core", thc(:).', "theta_plain",
              thp(:).', "theta_oe", tho.', "max_rel_difference",
              max (abs (thc(:) - thp(:)) ./ abs (thp(:))));
  printf ("frequency-domain OE, K = %d frequencies, [nb nf] = [%d %d]\n",
          K, nb, nf);
  printf ("  core LM from th0:  %.4f s CPU (%d iterations), loss %.6g\n",
          tc, ic.iterations, loss (thc(:)));
  printf ("  plain Octave LM:   %.4f s CPU (%d iterations), loss %.6g\n",
          tp, itp, loss (thp(:)));
  printf ("  ratio %.1fx; max |theta_core - theta_plain| / |theta| = %.1e\n",
          S.ratio, S.max_rel_difference);
  printf ("  oe (Gfrd, [2 2]) end to end (SRIVC start + LM): %.4f s CPU, ",
          to);
  printf ("max rel. difference to the plain LM %.1e\n",
          max (abs (tho - thp(:)) ./ abs (thp(:))));
endfunction

function t = best_cpu (f, R)
  t = Inf;
  for r = 1:R
    c0 = cputime ();
    f ();
    t = min (t, cputime () - c0);
  endfor
endfunction

## Levenberg-Marquardt on sum |G - B/F (jw)|^2, theta = [f; b] (F monic,
## descending powers), vectorised complex arithmetic.
function [theta, iters] = plain_lm (w, G, nf, nb, theta)
  s = 1i * w;
  Pf = s .^ (nf-1:-1:0);            # powers for f1 .. f_nf
  Pb = s .^ (nb-1:-1:0);            # powers for b_0 .. b_(nb-1)
  sn = s .^ nf;
  np = nf + nb;
  mu = 1e-3;
  [e, J] = residual (theta);
  cost = e' * e;
  iters = 0;
  for it = 1:100
    sc = sqrt (sum (J .^ 2)).';
    sc(sc == 0) = 1;
    [Q, Rr] = qr (J ./ sc.', 0);
    qte = Q' * e;
    accepted = false;
    for a = 1:40
      step = ([Rr; sqrt(mu) * eye(np)] \ [qte; zeros(np, 1)]) ./ sc;
      trial = theta + step;
      if (all (real (roots ([1; trial(1:nf)])) < 0))
        et = residual (trial);
        c = et' * et;
        if (c < cost)
          accepted = true;
          break;
        endif
      endif
      mu *= 10;
    endfor
    if (! accepted)
      break;
    endif
    rel = norm (step .* sc) / norm (theta .* sc);
    dec = (cost - c) / cost;
    theta = trial;
    cost = c;
    mu = max (mu / 10, 1e-12);
    iters = it;
    [e, J] = residual (theta);
    if (rel <= 1e-10 && dec <= 1e-10)
      break;
    endif
  endfor

  ## e = [Re; Im] (G - B/F), J = d yhat / d theta stacked the same way
  function [e, J] = residual (th)
    F = sn + Pf * th(1:nf);
    Bv = Pb * th(nf+1:end);
    H = Bv ./ F;
    E = G - H;
    e = [real(E); imag(E)];
    if (nargout > 1)
      Jc = [-Pf .* (H ./ F), Pb ./ F];
      J = [real(Jc); imag(Jc)];
    endif
  endfunction
endfunction

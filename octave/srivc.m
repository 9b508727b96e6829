## -*- texinfo -*-
## @deftypefn  {} {@var{M} =} srivc (@var{data}, [@var{nb} @var{nf} @var{nk}])
## @deftypefnx {} {@var{M} =} srivc (@var{data}, [@var{nb1} @dots{} @var{nbm} @var{nf1} @dots{} @var{nfm} @var{nk1} @dots{} @var{nkm}])
## @deftypefnx {} {@var{M} =} srivc (@dots{}, @var{name}, @var{value})
## @deftypefnx {} {[@var{M}, @var{RT2}, @var{YIC}, @var{info}] =} srivc (@dots{})
## Simplified refined instrumental variable estimate of a continuous-time
## transfer function B(p)/F(p) (SRIVC, thesis eqs. 2.8-2.13), optimal for
## output-error models with white noise.
##
## @var{nn} = [nb nf nk]: nb numerator and nf denominator parameters, nk the
## input delay in samples; with m inputs nb and nk have m entries and F is
## common to all inputs. CONTSID's MISO form [nb1..nbm nf1..nfm nk1..nkm]
## (3m entries) gives each input its own denominator F_j ('Different'
## denominators, CONTSID 7.3's default): y = sum_j B_j/F_j u_j, estimated
## by refined IV steps on each input in turn (backfitting).
## Options:
## @table @code
## @item Tol, MaxIter
## stop when the relative change of the parameters falls below Tol
## (default 1e-6), or after MaxIter iterations (default 30).
## @item lambda
## cut-off (rad/s) of the SVF of the IVSVF start. Default: IVSVF at 12
## cut-offs log-spaced over the record's band, ranked by the simulation
## error of the start model; SRIVC runs from the best @code{MaxStarts}
## (default 3) starts and keeps the best stable, converged model.
## @item InitMethod
## @qcode{"ivsvf"} (default), or a stable initial model (an @code{idctm}
## or its [f1 .. f_nf, b ..] values).
## @item InitialState
## @qcode{"zero"} (default) or @qcode{"estimate"}: the free response of an
## unknown initial state is estimated with the model (linear least squares
## on the free responses at each iteration); @var{info}.x0 holds the
## initial derivatives y0(t0), y0'(t0), .. of each denominator's part.
## @item OutputOffset, InputOffset
## estimate a constant output offset c (y = x + c + e), or an offset d_j
## of each input (u_j + d_j enters the model); default false. Reported in
## @var{info}.offset and @var{info}.input_offset.
## @item TimeScale
## @qcode{"auto"} (default): the iterations run in a time t' = s t with s
## the model's characteristic frequency |F(0)|^(1/nf), which keeps
## high-order or fast-sampled models well conditioned; or a given s.
## @end table
##
## Every iterate is kept stable (an unstable IV solution is pulled back
## toward the previous iterate by step halving, reflected as a last resort).
## A model that did not converge gives the warning @code{srivc:notConverged}
## (and the last iterate); an unstable one @code{srivc:unstable}.
## Outputs: the @code{idctm} model @var{M} (with covariance, noise variance,
## iterations and converged), @var{RT2} = 1 - var(e)/var(y) of the
## simulation error e, the Young information criterion @var{YIC} =
## log(var(e)/var(y)) + log(mean(P_ii / theta_i^2)), and @var{info}
## (converged, stable, iterations, reason, noise_variance, lambda,
## time_scale, starts, condition, x0, offset, input_offset, simulated).
##
## @strong{Example}
## @example
## u = prbs (10, 8); Ts = 0.05; N = numel (u);
## y = simc (idctm (4, [1 2.4 4]), u, Ts) + 0.2 * randn (N, 1);
## [M, RT2] = srivc (iddata (y, u, Ts, "InterSample", "zoh"), [1 2 0])
## @end example
## @seealso{clsrivc, ivsvf, srivcstruc, rsrivc, comparec}
## @end deftypefn

function [M, RT2, YIC, info] = srivc (varargin)
  [M, RT2, YIC, info] = contsid_offline ("srivc", varargin);
endfunction

%!shared u, Ts, x, N
%! u = prbs (10, 8); Ts = 0.05; N = numel (u);
%! x = simc (idctm (4, [1 2.4 4]), u, Ts);

%!test  # noise-free: exact (the prefilter with the true F makes it so)
%! [M, RT2] = srivc (iddata (x, u, Ts), [1 2 0], "lambda", 3, "Tol", 1e-12);
%! assert (M.F, [1 2.4 4], 1e-9);
%! assert (M.B, 4, 1e-9);
%! assert (RT2, 1, 1e-9);
%! assert (M.converged);

%!test  # default start (grid of cut-offs), noisy data: close and converged
%! randn ("state", 4);
%! y = x + 0.2 * randn (N, 1);
%! [M, RT2, YIC] = srivc (iddata (y, u, Ts), [1 2 0]);
%! assert (M.theta, [2.4 4 4], 0.15);
%! assert (RT2 > 0.5);
%! assert (isfinite (YIC));
%! assert (all (sqrt (diag (M.covariance)) < 0.2));

%!test  # an initial model; tf conversion; simc of the result
%! M = srivc (iddata (x, u, Ts), [1 2 0], "InitMethod", idctm (3, [1 2 3]), "Tol", 1e-12);
%! assert (M.theta, [2.4 4 4], 1e-8);
%! yh = simc (M, u, Ts);
%! assert (yh, x, 1e-8);
%! pkg load control
%! G = tf (M);
%! assert (isa (G, "tf"));

%!warning <no convergence> srivc (iddata (x + 0.3 * sin ((1:N)'), u, Ts), [1 2 0], "lambda", 3, "MaxIter", 1);

%!error id=srivc:badInput srivc (iddata (x, u, Ts), [1 2 0], "Tol", 0)
%!error id=srivc:badInput srivc (iddata (x, u, Ts), [1 2 0], "MaxIter", 0)
%!error id=srivc:badOption srivc (iddata (x, u, Ts), [1 2 0], "InitMethod", "magic")
%!error id=srivc:badInput srivc (iddata (x, u, Ts), [1 2 0], "InitMethod", [-1 4 4])
%!error id=srivc:badInput srivc (iddata (x, u, Ts), [1 2 0], "lambda", -1)
%!error id=srivc:badInput srivc (iddata (x, u, Ts), [4 2 0])
%!error id=srivc:badOption srivc (iddata (x, u, Ts), [1 2 0], "bogus", 1)

%!demo
%! u = prbs (10, 8); Ts = 0.05; N = numel (u);
%! y = simc (idctm (4, [1 2.4 4]), u, Ts) + 0.2 * randn (N, 1);
%! data = iddata (y, u, Ts, "InterSample", "zoh");
%! M = srivc (data, [1 2 0])
%! comparec (data, M);

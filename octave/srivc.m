## -*- texinfo -*-
## @deftypefn  {} {@var{M} =} srivc (@var{data}, [@var{nb} @var{nf} @var{nk}])
## @deftypefnx {} {@var{M} =} srivc (@dots{}, @var{name}, @var{value})
## @deftypefnx {} {[@var{M}, @var{RT2}, @var{YIC}] =} srivc (@dots{})
## Simplified refined instrumental variable estimate of a continuous-time
## transfer function B(p)/F(p) (SRIVC, thesis eqs. 2.8-2.13), optimal for
## output-error models with white noise.
##
## @var{nn} = [nb nf nk]: nb numerator and nf denominator parameters, nk the
## input delay in samples. Options:
## @table @code
## @item Tol, MaxIter
## stop when the relative change of the parameters falls below Tol
## (default 1e-6), or after MaxIter iterations (default 20); then a warning
## @code{srivc:notConverged} is raised and the last iterate returned.
## @item lambda
## cut-off (rad/s) of the SVF of the IVSVF start. Default: SRIVC is run
## from IVSVF starts at 12 cut-offs log-spaced over the record's band and
## the model with the smallest simulation-error variance is kept.
## @item InitMethod
## @qcode{"ivsvf"} (default), or a stable initial model (an @code{idctm}
## or its [f1 .. f_nf, b ..] values).
## @end table
##
## Every iterate is stability-checked: unstable roots of F are reflected
## before they drive the prefilter 1/F(p) and the auxiliary model. Outputs:
## the @code{idctm} model @var{M} (with covariance and noise variance),
## @var{RT2} = 1 - var(e)/var(y) of the simulation error e, and the Young
## information criterion @var{YIC} = log(var(e)/var(y)) + log(mean(P_ii /
## theta_i^2)).
##
## @strong{Example}
## @example
## u = prbs (10, 8); Ts = 0.05; N = numel (u);
## y = simc (idctm (4, [1 2.4 4]), u, Ts) + 0.2 * randn (N, 1);
## [M, RT2] = srivc (iddata (y, u, Ts, "InterSample", "zoh"), [1 2 0])
## @end example
## @seealso{clsrivc, ivsvf, rsrivc, comparec}
## @end deftypefn

function [M, RT2, YIC, varargout] = srivc (varargin)
  contsid_nargchk ("srivc", nargin, nargout, [0 Inf], 3);
  [M, RT2, YIC] = contsid_offline ("srivc", varargin);
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

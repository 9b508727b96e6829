## -*- texinfo -*-
## @deftypefn  {} {[@var{sys}, @var{sysN}] =} tfrivc (@var{data}, @var{np}, @var{nz}, 'NN', [@var{nd} @var{nc}])
## @deftypefnx {} {[@var{sys}, @var{sysN}] =} tfrivc (@var{data}, @var{np}, @var{nz}, @var{IODelay}, @dots{})
## @deftypefnx {} {[@var{sys}, @var{sysN}] =} tfrivc (@dots{}, @var{name}, @var{value}, @dots{})
## Continuous-time transfer function with a time delay and a discrete
## ARMA noise model,
## @example
## y(t_k) = B(p)/F(p) u(t_k - td) + C(q^-1)/D(q^-1) e(t_k),
## deg F = np, deg B = nz, deg D = nd, deg C = nc,
## @end example
## by refined IV: @code{tfsrivc} gives the delay td (search and
## refinement, or fixed with 'FixTd') and the start; RIVC
## (core/include/ctid/offline/refined_iv_bj.hpp, as @code{rivc}) then iterates
## the plant and the noise model with td kept, the delayed input filtered
## exactly for any fraction of a sample.
##
## @var{data}: @code{iddata} (regular sampling). Options: @code{'NN'},
## [nd nc] (default [0 0]: then the result is tfsrivc's plant re-iterated
## by the same engine); all others (@code{FixTd}, @code{TdMin},
## @code{TdMax}, @code{NumTd}, @code{Lambda}, @code{MaxIter},
## @code{TolPar}, ...) go to @code{tfsrivc} (MaxIter and TolPar also
## stop the RIVC iterations).
##
## @var{sys}: an @code{idtf} with IODelay = td, the covariance of [b; f]
## (sigma_e^2 (sum zeta_f zeta_f')^-1, eq. 2.13; td counted as known),
## @code{Report.Fit}, @code{Report.Parameters.NoiseModel}.
## @var{sysN}: the noise model, a discrete @code{idpoly} C/D (B = C,
## F = D, CONTSID's @code{idpoly (1, C, 1, 1, D, 0, Ts)} form) with
## NoiseVariance sigma_e^2.
##
## @strong{Example}
## @example
## Ts = 0.05; u = kron (sign (randn (300, 1)), ones (10, 1));
## M0 = idtf (4, [1 1.2 4], "IODelay", 0.37);
## x = simc (M0, iddata ([], u, Ts, "InterSample", "zoh"));
## v = filter ([1 0.5], [1 -0.9], 0.05 * randn (3000, 1));
## [MP, MN] = tfrivc (iddata (x + v, u, Ts), 2, 0, "NN", [1 1])
## @end example
## @seealso{tfsrivc, rivc}
## @end deftypefn

function [sys, sysN, varargout] = tfrivc (varargin)
  contsid_nargchk ("tfrivc", nargin, nargout, [3 Inf], 2);
  [sys, info, d] = contsid_rivc ("tfrivc", varargin);
  sysN = [];
  if (nargout > 1)
    sysN = idpoly (1, info.C, 1, 1, info.D, info.noise_variance, d.Ts);
  endif
endfunction

%!shared u, x, Ts, N, M0
%! Ts = 0.05; N = 3000; randn ("state", 3);
%! u = kron (sign (randn (N / 10, 1)), ones (10, 1));
%! M0 = idtf (4, [1 1.2 4], "IODelay", 0.37);
%! x = simc (M0, iddata ([], u, Ts, "InterSample", "zoh"));

%!test  # noise-free, delay a fraction of a sample, kept: exact
%! [MP, MN] = tfrivc (iddata (x, u, Ts), 2, 0, 0.37, "FixTd", "on", ...
%!                    "NN", [1 1]);
%! assert (MP.IODelay, 0.37);
%! assert ([MP.num{1}, MP.den{1}], [4 1 1.2 4], 1e-7);
%! assert (isa (MN, "idpoly") && MN.Ts == Ts);

%!test  # coloured noise: the noise model and the reported sd
%! randn ("state", 8);
%! v = filter ([1 0.5], [1 -0.9], 0.05 * randn (N, 1));
%! [MP, MN] = tfrivc (iddata (x + v, u, Ts), 2, 0, 0.37, "FixTd", "on", ...
%!                    "NN", [1 1]);
%! sd = sqrt (diag (getcov (MP)))(1:3).';   # [b f], then the IODelay
%! assert (all (abs ([MP.num{1}, MP.den{1}(2:3)] - [4 1.2 4]) < 4 * sd));
%! assert (MN.F(2), -0.9, 0.05);
%! assert (MN.B(2), 0.5, 0.1);

%!error id=tfrivc:badInput tfrivc (iddata (x, u, Ts), 2)
%!error id=tfrivc:badInput tfrivc (iddata (x, u, Ts), 0, 0, "NN", [1 1])
%!error id=tfrivc:badInput tfrivc (iddata (x, u, Ts), 2, 3, "NN", [1 1])
%!error id=tfrivc:badInput tfrivc (iddata (x, u, Ts), 2, 0, -1, "NN", [1 1])
%!error id=tfrivc:badInput tfrivc (iddata (x, u, Ts), 2, 0, "NN", [1 1 1])
%!error id=tfrivc:badInput tfrivc (iddata (x, u, Ts), 2, 0, "NN")
%!error id=tfrivc:badInput tfrivc (iddata (x, u, Ts), 2, 0, 3, 4)
%!error id=tfrivc:badOption tfrivc (iddata (x, u, Ts), 2, 0, 0.37, "FixTd", "on", "Bogus", 1)
%!error id=tfrivc:badOption tfrivc (iddata (x, u, Ts), 2, 0, 0.37, "FixTd", "on", "MaxIter", 0)

%!demo
%! Ts = 0.05; u = kron (sign (randn (300, 1)), ones (10, 1));
%! M0 = idtf (4, [1 1.2 4], "IODelay", 0.37);
%! x = simc (M0, iddata ([], u, Ts, "InterSample", "zoh"));
%! v = filter ([1 0.5], [1 -0.9], 0.05 * randn (3000, 1));
%! [MP, MN] = tfrivc (iddata (x + v, u, Ts), 2, 0, "NN", [1 1])

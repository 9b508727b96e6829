## -*- texinfo -*-
## @deftypefn  {} {[@var{M}, @var{C}, @var{D}] =} rivc (@var{data}, [@var{nb} @var{nc} @var{nd} @var{nf} @var{nk}])
## @deftypefnx {} {[@var{M}, @var{C}, @var{D}, @var{RT2}, @var{YIC}, @var{Cond_IPM}, @var{AIC}] =} rivc (@dots{})
## @deftypefnx {} {@dots{} =} rivc (@var{data}, @var{Mi})
## @deftypefnx {} {@dots{} =} rivc (@dots{}, @var{name}, @var{value}, @dots{})
## Refined instrumental-variable estimate (RIVC, Young and Garnier) of the
## hybrid Box-Jenkins model
## @example
## y(t_k) = B(p)/F(p) u(t_k - nk Ts) + C(q^-1)/D(q^-1) e(t_k)
## @end example
## a continuous-time plant with a discrete-time ARMA noise model.
##
## Each iteration (core/include/ctid/refined_iv_bj.hpp) simulates the
## auxiliary model x_hat = B/F u, fits an ARMA model D xi = C e to the
## noise estimate xi = y - x_hat (Hannan-Rissanen, then Gauss-Newton
## prediction-error steps), and solves the IV equations of thesis
## eqs. 2.10-2.12 with the hybrid prefilter: 1/F(p) in continuous time
## (exact ZOH/FOH filters), then D/C on the samples (eq. 2.9 with the
## Box-Jenkins optimal prefilter). The start is SRIVC (eqs. 2.8-2.13).
## With nc = nd = 0 this is SRIVC.
##
## @var{data}: an @code{iddata} (one output, one input, regular sampling,
## InterSample 'zoh' or 'foh'). Orders: B has nb parameters (1 <= nb <=
## nf + 1), F order nf, C order nc, D order nd, delay nk samples.
## @var{Mi}: an @code{idpoly} whose B, C, D, F give the orders and whose
## B, F start the iterations.
##
## Options: @code{lambda} (SVF cut-off of the SRIVC start, rad/s),
## @code{Tol} (1e-6, relative parameter change), @code{MaxIter} (30),
## @code{InitMethod} ('srivc', an @code{idpoly} or [f b]),
## @code{ArmaMethod} ('pem'; CONTSID's 'ivarma' is not implemented),
## @code{ArmaMaxIter} (50).
##
## @var{M}: a continuous-time @code{idpoly} B/F with the covariance of
## [f b], sigma_e^2 (sum zeta_f zeta_f')^-1 (eq. 2.13 with the innovation
## variance sigma_e^2 of the noise model), @code{Report.NoiseModel}
## (C, D, NoiseVariance, Ts) and @code{Report.Fit}. @var{C}, @var{D}:
## the noise polynomials in q^-1 (rows [1 c1 ..], [1 d1 ..]). @var{RT2}:
## 1 - var(y - x_hat)/var(y); @var{YIC}; @var{Cond_IPM}: the condition
## number of the instrumental product matrix; @var{AIC}:
## log(sigma_e^2) + 2 (nb + nf + nc + nd)/N. A run that does not
## converge warns @code{rivc:notConverged} and returns the last iterate.
##
## @strong{Example}
## @example
## pkg load control
## Ts = 0.05; u = kron (sign (randn (400, 1)), ones (10, 1));
## x = lsim (c2d (tf ([1.5 4], [1 1.2 4]), Ts), u);
## v = filter ([1 0.5], [1 -0.9], 0.3 * randn (4000, 1));
## [M, C, D] = rivc (iddata (x + v, u, Ts), [2 1 1 2 0])
## @end example
## @seealso{srivc, tfrivc, clrivc, cl2srivc}
## @end deftypefn

function [M, C, varargout] = rivc (varargin)
  contsid_nargchk ("rivc", nargin, nargout, [2 Inf], 7);
  [M, info] = contsid_rivc ("rivc", varargin);
  C = info.C;
  out = {info.D, info.RT2, info.YIC, info.condition, info.AIC};
  varargout = out(1:max (nargout - 2, 0));
endfunction

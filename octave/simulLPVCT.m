## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{y} =} simulLPVCT (@var{u}, @var{A}, @var{DepA}, @var{B}, @var{DepB}, @var{Ts})
## Simulate a continuous-time linear parameter-varying (LPV) input/output
## model on sampled data.
##
## The model, whose coefficients depend on a scheduling signal rho and
## multiply the derivatives,
## @example
## a0 y^(na) + a1(rho) y^(na-1) + .. + a_na(rho) y = b1(rho) u^(nb-1) + .. + b_nb(rho) u
## @end example
## with @code{a_i(rho(t_k)) = sum_j A(i+1, j) DepA(j, i, k)} and
## @code{b_i(rho(t_k)) = sum_j B(i, j) DepB(j, i, k)}:
## @table @var
## @item u
## input, a vector of N samples.
## @item A
## (na+1)-by-n_dep matrix of coefficients; its first row is the constant
## leading coefficient [a0 0 .. 0].
## @item DepA
## n_dep-by-na-by-N array: the basis functions of coefficient a_i evaluated
## at the samples in @code{DepA(:, i, :)}; a row of zeros is a basis
## function that is not used.
## @item B, DepB
## nb-by-n_dep coefficients and n_dep-by-nb-by-N basis functions of the
## numerator; B's first row is b1, the coefficient of the highest input
## derivative.
## @item Ts
## sampling interval.
## @end table
##
## @var{y} is the noise-free output (N-by-1), the system at rest before
## the first sample.  Derivatives are backward (Euler) differences
## (1 - q^-1)/Ts and the equation is solved at each sample for y_k
## (implicit Euler, first order in @var{Ts}: @var{Ts} must be small with
## respect to the time constants); @code{lpvsrivc} and @code{lpvrivc} use
## the same operator.
##
## @strong{Example} (the system a1 = 2 - 1.5 rho + 2 rho^2, a2 = 5 + 3 rho,
## b1 = 3 + 2 cos(rho), b2 = 5 - 3 sin(2 rho))
## @example
## Ts = 0.005; t = 0:Ts:15; p = sin (2*pi/3*t); u = rand (numel (t), 1)*2 - 1;
## DepA(:,1,:) = [ones(size(p)); p; p.^2];
## DepA(:,2,:) = [ones(size(p)); p; zeros(size(p))];
## DepB(:,1,:) = [ones(size(p)); cos(p)];
## DepB(:,2,:) = [ones(size(p)); sin(2*p)];
## A = [1 0 0; 2 -1.5 2; 5 3 0]; B = [3 2; 5 -3];
## y = simulLPVCT (u, A, DepA, B, DepB, Ts);
## @end example
## @seealso{lpvsrivc, lpvrivc, extractPoles, extractZeros}
## @end deftypefn

function varargout = simulLPVCT (varargin)
  varargout = contsid_guard ("simulLPVCT", @simulLPVCT_body, nargout, varargin);
endfunction

function varargout = simulLPVCT_body (varargin)
  contsid_nargchk ("simulLPVCT", nargin, nargout, [6 6], 1);
  fname = "simulLPVCT";
  [u, A, DepA, B, DepB, Ts] = varargin{:};
  if (! (isnumeric (u) && isreal (u) && isvector (u)))
    error ("simulLPVCT:badInput", "simulLPVCT: u must be a real vector");
  endif
  if (! (isnumeric (Ts) && isreal (Ts) && isscalar (Ts) && Ts > 0
         && isfinite (Ts)))
    error ("simulLPVCT:badInput", "simulLPVCT: Ts must be a positive scalar");
  endif
  for [m, name] = struct ("A", A, "B", B)
    if (! (isnumeric (m) && isreal (m) && ismatrix (m) && ! isempty (m)))
      error ("simulLPVCT:badInput", "simulLPVCT: %s must be a real matrix",
             name);
    endif
  endfor
  [dep_a, dims_a] = lpv_dependency (fname, DepA, "DepA");
  [dep_b, dims_b] = lpv_dependency (fname, DepB, "DepB");
  if (dims_a(3) != numel (u) || dims_b(3) != numel (u))
    error ("simulLPVCT:dimensionMismatch",
           "simulLPVCT: DepA and DepB must have one page per sample of u (%d), got %d and %d",
           numel (u), dims_a(3), dims_b(3));
  endif
  opts = struct ("Ts", double (Ts), "A", double (A), "B", double (B),
                 "dims_a", dims_a, "dims_b", dims_b);
  varargout{1} = lpv_mex (fname, double (u(:)), dep_a, dep_b, opts);
endfunction

%!shared Ts, t, p, u, A, B, DepA, DepB
%! Ts = 0.005; t = (0:Ts:10)'; p = sin (2*pi/3*t');
%! u = sin (1.3*t) + 0.5*sin (3.1*t);
%! DepA = zeros (3, 2, numel (t)); DepB = zeros (2, 2, numel (t));
%! DepA(:,1,:) = [ones(size(p)); p; p.^2];
%! DepA(:,2,:) = [ones(size(p)); p; zeros(size(p))];
%! DepB(:,1,:) = [ones(size(p)); cos(p)];
%! DepB(:,2,:) = [ones(size(p)); sin(2*p)];
%! A = [1 0 0; 2 -1.5 2; 5 3 0]; B = [3 2; 5 -3];

## Against an independent integration of the LPV differential equation
## (ode45, smooth input with its exact derivative): the Euler recursion is
## first order, so halving Ts halves the error.
%!test
%! rho = @(tt) sin (2*pi/3*tt);
%! uu = @(tt) sin (1.3*tt) + 0.5*sin (3.1*tt);
%! du = @(tt) 1.3*cos (1.3*tt) + 1.55*cos (3.1*tt);
%! f = @(tt, x) [x(2); -(2 - 1.5*rho(tt) + 2*rho(tt)^2)*x(2) ...
%!               - (5 + 3*rho(tt))*x(1) + (3 + 2*cos (rho(tt)))*du(tt) ...
%!               + (5 - 3*sin (2*rho(tt)))*uu(tt)];
%! opt = odeset ("RelTol", 1e-10, "AbsTol", 1e-12);
%! [~, x] = ode45 (f, t, [0; 0], opt);
%! y = simulLPVCT (u, A, DepA, B, DepB, Ts);
%! e1 = max (abs (y - x(:,1))) / max (abs (x(:,1)));
%! t2 = (0:Ts/2:10)'; p2 = sin (2*pi/3*t2');
%! DepA2 = zeros (3, 2, numel (t2)); DepB2 = zeros (2, 2, numel (t2));
%! DepA2(:,1,:) = [ones(size(p2)); p2; p2.^2];
%! DepA2(:,2,:) = [ones(size(p2)); p2; zeros(size(p2))];
%! DepB2(:,1,:) = [ones(size(p2)); cos(p2)];
%! DepB2(:,2,:) = [ones(size(p2)); sin(2*p2)];
%! y2 = simulLPVCT (uu (t2), A, DepA2, B, DepB2, Ts/2);
%! e2 = max (abs (y2(1:2:end) - x(:,1))) / max (abs (x(:,1)));
%! assert (e1 < 0.02);
%! assert (e1 / e2, 2, 0.3);

## A time-invariant model is the Euler discretisation of its transfer
## function: y' + 2 y = 3 u gives (1 + 2 Ts) y_k - y_(k-1) = 3 Ts u_k.
%!test
%! N = 200; v = randn (N, 1);
%! y = simulLPVCT (v, [1; 2], ones (1, 1, N), 3, ones (1, 1, N), 0.1);
%! assert (y, filter (3*0.1, [1 + 2*0.1, -1], v), 1e-12);

%!error <Invalid call|called with> simulLPVCT (1, 2)
%!error id=simulLPVCT:dimensionMismatch simulLPVCT (u(1:end-1), A, DepA, B, DepB, Ts)
%!error id=simulLPVCT:dimensionMismatch simulLPVCT (u, A(1:2,:), DepA, B, DepB, Ts)
%!error id=simulLPVCT:dimensionMismatch simulLPVCT (u, A, DepA, B(:,1), DepB, Ts)
%!error id=simulLPVCT:badInput simulLPVCT (u, [0 0 0; A(2:3,:)], DepA, B, DepB, Ts)
%!error id=simulLPVCT:badInput simulLPVCT (u, A, DepA, B, DepB, -1)
%!error id=simulLPVCT:badInput simulLPVCT (u, A, {DepA}, B, DepB, Ts)
## A recursion with no solution: 1/Ts^2 - 1/Ts + 0 = 0 at Ts = 1.
%!error id=simulLPVCT:numericalFailure simulLPVCT (ones (5, 1), [1; -1; 0], ones (1, 2, 5), 1, ones (1, 1, 5), 1)

%!demo
%! ## CONTSID's LPV example: output of the LPV system, scheduling signal
%! Ts = 0.005; t = 0:Ts:15; p = sin (2*pi/3*t); u = rand (numel (t), 1)*2 - 1;
%! DepA = zeros (3, 2, numel (t)); DepB = zeros (2, 2, numel (t));
%! DepA(:,1,:) = [ones(size(p)); p; p.^2];
%! DepA(:,2,:) = [ones(size(p)); p; zeros(size(p))];
%! DepB(:,1,:) = [ones(size(p)); cos(p)];
%! DepB(:,2,:) = [ones(size(p)); sin(2*p)];
%! y = simulLPVCT (u, [1 0 0; 2 -1.5 2; 5 3 0], DepA, [3 2; 5 -3], DepB, Ts);
%! subplot (2, 1, 1); plot (t, y); title ("noise-free output");
%! subplot (2, 1, 2); plot (t, p); title ("scheduling variable");

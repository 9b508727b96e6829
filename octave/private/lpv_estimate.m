## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {[@var{th}, @var{infos}, @var{ysim}, @var{c}, @var{d}] =} lpv_estimate (@var{fname}, @var{nnlen}, @var{args})
## Shared argument handling of @code{lpvsrivc} and @code{lpvrivc}:
## @var{args} = @{data, nn, DepA, DepB [, tol, maxiter, Ainit, Binit]@}
## (data: an iddata object or y, u, Ts), @var{nn} = [nb na] (@var{nnlen}
## 2) or [nb na nc nd] (@var{nnlen} 4).  Calls
## the gateway @code{lpv_mex} and builds the @var{infos} struct
## (J, Iteration, converged, Arivc, Brivc).
## @end deftypefn

function [th, infos, ysim, c, d] = lpv_estimate (fname, nnlen, args)
  data = contsid_getdata (fname, args{:});
  args = args(data.nconsumed:end);
  if (numel (args) < 4 || numel (args) > 8)
    error ([fname ":badInput"],
           "%s: expected data, nn, DepA, DepB [, tol, maxiter, Ainit, Binit]",
           fname);
  endif
  nn = args{2};
  if (! (isnumeric (nn) && isreal (nn) && numel (nn) == nnlen
         && all (nn == fix (nn)) && all (nn(1:2) >= 1) && all (nn >= 0)))
    if (nnlen == 2)
      error ([fname ":badInput"], "%s: nn must be [nb na], positive integers",
             fname);
    else
      error ([fname ":badInput"],
             "%s: nn must be [nb na nc nd], integers with nb, na >= 1", fname);
    endif
  endif
  if (columns (data.u) != 1)
    error ([fname ":notSupported"],
           "%s: one input only (the data have %d)", fname, columns (data.u));
  endif
  if (! data.uniform)
    error ([fname ":notSupported"],
           "%s: the data must be uniformly sampled", fname);
  endif
  [dep_a, dims_a] = lpv_dependency (fname, args{3}, "DepA");
  [dep_b, dims_b] = lpv_dependency (fname, args{4}, "DepB");
  if (nn(1) != dims_b(2) || nn(2) != dims_a(2))
    error ([fname ":dimensionMismatch"],
           "%s: nn gives nb = %d and na = %d but DepB has %d and DepA %d coefficients (second dimension)",
           fname, nn(1), nn(2), dims_b(2), dims_a(2));
  endif
  tol = 1e-4;
  maxiter = 50;
  a_init = [];
  b_init = [];
  if (numel (args) >= 5 && ! isempty (args{5}))
    tol = args{5};
    if (! (isnumeric (tol) && isreal (tol) && isscalar (tol) && tol > 0))
      error ([fname ":badOption"], "%s: tol must be a positive scalar", fname);
    endif
  endif
  if (numel (args) >= 6 && ! isempty (args{6}))
    maxiter = args{6};
    if (! (isnumeric (maxiter) && isreal (maxiter) && isscalar (maxiter)
           && maxiter >= 1 && maxiter <= 10000 && maxiter == fix (maxiter)))
      error ([fname ":badOption"],
             "%s: maxiter must be an integer in 1..10000", fname);
    endif
  endif
  if (numel (args) >= 7)
    a_init = args{7};
  endif
  if (numel (args) >= 8)
    b_init = args{8};
  endif
  for [m, name] = struct ("Ainit", a_init, "Binit", b_init)
    if (! isempty (m) && ! (isnumeric (m) && isreal (m) && ismatrix (m)
                            && all (isfinite (m(:)))))
      error ([fname ":badInput"], "%s: %s must be a finite real matrix",
             fname, name);
    endif
  endfor
  if (isempty (a_init) != isempty (b_init))
    error ([fname ":badInput"], "%s: give Ainit and Binit together", fname);
  endif
  noise = [0 0];
  if (numel (nn) == 4)
    noise = nn(3:4);
  endif
  opts = struct ("Ts", double (data.Ts), "dims_a", dims_a, "dims_b", dims_b,
                 "nc", noise(1), "nd", noise(2), "tol", double (tol),
                 "maxiter", double (maxiter), "Ainit", double (a_init),
                 "Binit", double (b_init));
  [th, A, B, c, d, J, iterations, converged, ysim] = ...
    lpv_mex (fname, double (data.y), double (data.u), dep_a, dep_b, opts);
  infos = struct ("J", J, "Iteration", iterations,
                  "converged", logical (converged), "Arivc", A, "Brivc", B);
endfunction

## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {[@var{theta}, @var{ni}, @var{noise}] =} pde_heat_iv (@var{fname}, @var{args}, @var{nn})
## Back-end of @code{pdesrivc4heatdiffusion} (@var{nn} empty) and
## @code{pderivc4heatdiffusion} (@var{nn} = [ndet ncet ndes nces]):
## @var{args} = @{Data1, Data2, IC[, tol[, maxiter]]@}.  @var{noise} is
## @{Cet, Det, Ces, Des@}.  Warns @code{@var{fname}:notConverged} when the
## iterations stop at maxiter.
## @end deftypefn

function [theta, ni, noise] = pde_heat_iv (fname, args, nn)
  [Data1, Data2, IC] = args{1:3};
  [t, x, y, u] = pde_heat_data (fname, Data1, Data2, true);
  if (! (isnumeric (IC) && isreal (IC) && isvector (IC)))
    error ([fname ":badInput"], "%s: IC must be a real vector", fname);
  endif
  if (numel (IC) != numel (x))
    error ([fname ":dimensionMismatch"],
           "%s: IC must have numel(Data2.x) = %d values", fname, numel (x));
  endif
  tol = 1e-6;
  maxiter = 50;
  if (numel (args) >= 4 && ! isempty (args{4}))
    tol = args{4};
    if (! (isnumeric (tol) && isscalar (tol) && isreal (tol) && tol > 0))
      error ([fname ":badOption"], "%s: tol must be a scalar > 0", fname);
    endif
  endif
  if (numel (args) >= 5 && ! isempty (args{5}))
    maxiter = args{5};
    if (! (isnumeric (maxiter) && isscalar (maxiter) && maxiter >= 1
           && maxiter == fix (maxiter)))
      error ([fname ":badOption"], "%s: maxiter must be an integer >= 1",
             fname);
    endif
  endif
  opts = struct ("t", t, "x", x, "ic", double (IC(:).'), "tol", double (tol),
                 "maxiter", double (maxiter));
  if (isempty (nn))
    [theta, ni, conv] = pde_mex (fname, y, u, opts);
    noise = {};
  else
    opts.nn = double (nn(:).');
    [theta, ni, conv, ct, dt, cs, ds] = pde_mex (fname, y, u, opts);
    noise = {ct, dt, cs, ds};
  endif
  if (! conv)
    warning ([fname ":notConverged"],
             "%s: no convergence in %d iterations (tol = %g)", fname, ni, tol);
  endif
endfunction

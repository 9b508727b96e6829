## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{r} =} lpv_frozen_roots (@var{fname}, @var{C}, @var{Dep}, @var{is_den})
## Roots of the frozen polynomials of an LPV model at every sample, for
## @code{extractPoles} (@var{is_den} true: @var{C} is A, its first row the
## constant leading coefficient) and @code{extractZeros} (@var{C} is B).
## Column k of @var{r} holds the roots at sample k, padded with NaN.
## @end deftypefn

function r = lpv_frozen_roots (fname, C, Dep, is_den)
  if (! (isnumeric (C) && isreal (C) && ismatrix (C) && ! isempty (C)
         && all (isfinite (C(:)))))
    error ([fname ":badInput"], "%s: the coefficients must be a finite real matrix",
           fname);
  endif
  [~, dims] = lpv_dependency (fname, Dep, "the dependency array");
  ncoef = dims(2);
  name = ifelse_text (is_den, "A", "B");
  expected = [ncoef + is_den, dims(1)];
  if (! isequal (size (C), expected))
    error ([fname ":dimensionMismatch"],
           "%s: %s must be %d-by-%d for this dependency array, got %d-by-%d",
           fname, name, expected, rows (C), columns (C));
  endif
  Dep = double (Dep);
  coef = C(1 + is_den:end, :);
  ## traj(i, k) = sum_j coef(i, j) Dep(j, i, k)
  traj = reshape (sum (repmat (coef.', 1, dims(3)) .* reshape (Dep, dims(1), []), 1),
                  ncoef, dims(3));
  if (is_den)
    traj = [repmat(C(1, 1), 1, dims(3)); traj];
  endif
  if (! all (isfinite (traj(:))))
    error ([fname ":numericalFailure"],
           "%s: the frozen coefficients overflow (not finite)", fname);
  endif
  nroots = rows (traj) - 1;
  r = NaN (nroots, dims(3));
  for k = 1:dims(3)
    z = roots (traj(:, k).');
    r(1:numel (z), k) = z;
  endfor
endfunction

function s = ifelse_text (c, a, b)
  if (c)
    s = a;
  else
    s = b;
  endif
endfunction

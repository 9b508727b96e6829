## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {} contsid_check_input (@var{fname}, @var{u}, @var{nb})
## Refuse a record whose input column @var{j} is zero at every present
## sample while the model has @code{@var{nb}(j) > 0} numerator
## coefficients for it: they are then not identifiable, and a recursive
## estimator would return its initial values as tracks.  Errors
## @code{@var{fname}:badInput} with a message starting with @var{fname}
## (the offline estimators refuse such a record too, at their normal
## equations).
## @end deftypefn

function contsid_check_input (fname, u, nb)
  for j = 1:columns (u)
    if (j <= numel (nb) && nb(j) > 0)
      uj = u(! isnan (u(:,j)), j);
      if (! any (uj))
        error ([fname ":badInput"],
               ["%s: input %d is zero at every sample: the model's ", ...
                "numerator cannot be identified (no excitation)"], fname, j);
      endif
    endif
  endfor
endfunction

%!error id=f:badInput contsid_check_input ("f", zeros (10, 1), 1)
%!error id=f:badInput
%! contsid_check_input ("f", [ones(10, 1), [NaN; zeros(9, 1)]], [1 2]);
%!test
%! contsid_check_input ("f", [ones(10, 1), zeros(10, 1)], [1 0]);
%! contsid_check_input ("f", [zeros(9, 1); 1], 2);

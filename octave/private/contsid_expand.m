## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{outs} =} contsid_expand (@var{outs}, @var{d})
## Bring the per-sample outputs of an estimator run on the present samples
## of a record with missing samples (see @code{contsid_recursive_args})
## back to the @var{N} rows of the full record.
##
## @var{outs} is the cell of outputs @{@var{thm}, @var{yh}, @var{pset},
## @var{info}@} (any leading part of it).  When @var{d} has no field
## @code{missing} (no sample was missing) @var{outs} is returned as is.
## Otherwise, at a missing sample the estimator made no update, so
## @var{thm}, @var{pset} and every per-sample field of @var{info} (the
## fields with one row per present sample) hold their value of the last
## present sample (the first present sample's before it); @var{yh} holds
## the model output of the last present sample, as the zero-order hold of
## the bridged record does; @code{info.innovation} and @code{info.error}
## are 0 there (no update was made).  In such a run
## @code{info.innovation} is 0 wherever no update was made, also at the
## present samples the estimator held (the @code{GapSettle} time after a
## gap, and before @code{tsls}), where the core marks it NaN: one mark of
## "no update", and no NaN left in the outputs of a bridged record.
## @var{info} gains the field @code{missing}: the @var{N}-by-1 logical mask
## of the missing samples.
##
## With or without missing samples, an @var{info} with the per-sample field
## @code{covariance_guard} (what the covariance protection did: 0 nothing,
## 1 repair, 2 ceiling, 3 both; 0 at a missing sample) gains its summary:
## @code{guard_samples}, the number of samples where it acted, and
## @code{guard_first}, the first of them (0: never).
## @end deftypefn

function outs = contsid_expand (outs, d)
  if (! isfield (d, "missing"))
    outs = summarise_guard (outs);
    return;
  endif
  present = ! d.missing;
  n = rows (d.y);
  src = cumsum (present);
  src(src == 0) = 1;                     # before the first present sample
  for k = 1:numel (outs)
    x = outs{k};
    if (k == 3 && isnumeric (x) && size (x, 3) == n && n > 1)
      outs{k} = x(:, :, src);
    elseif (k == 4 && isstruct (x))
      outs{k} = expand_info (x, src, n, d.missing);
    elseif (isnumeric (x) && rows (x) == n)
      outs{k} = x(src, :);
    endif
  endfor
  outs = summarise_guard (outs);
endfunction

function outs = summarise_guard (outs)
  if (numel (outs) >= 4 && isstruct (outs{4})
      && isfield (outs{4}, "covariance_guard"))
    acted = outs{4}.covariance_guard != 0;
    outs{4}.guard_samples = nnz (acted);
    first = find (acted, 1);
    if (isempty (first))
      first = 0;
    endif
    outs{4}.guard_first = first;
  endif
endfunction

function info = expand_info (info, src, n, missing)
  names = fieldnames (info);
  for j = 1:numel (names)
    x = info.(names{j});
    if (isnumeric (x) || islogical (x)) && rows (x) == n && n > 1
      x = x(src, :);
      zeroed = {"innovation", "error", "covariance_guard"};
      if (any (strcmp (names{j}, zeroed)))
        x(missing, :) = 0;
      endif
      if (strcmp (names{j}, "innovation"))
        x(isnan (x)) = 0;                # held: no update made
      endif
      info.(names{j}) = x;
    endif
  endfor
  info.missing = missing;
endfunction

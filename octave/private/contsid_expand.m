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
## are 0 there (no update was made).  @var{info} gains the field
## @code{missing}: the @var{N}-by-1 logical mask of the missing samples.
## @end deftypefn

function outs = contsid_expand (outs, d)
  if (! isfield (d, "missing"))
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
endfunction

function info = expand_info (info, src, n, missing)
  names = fieldnames (info);
  for j = 1:numel (names)
    x = info.(names{j});
    if (isnumeric (x) || islogical (x)) && rows (x) == n && n > 1
      x = x(src, :);
      if (any (strcmp (names{j}, {"innovation", "error"})))
        x(missing, :) = 0;
      endif
      info.(names{j}) = x;
    endif
  endfor
  info.missing = missing;
endfunction

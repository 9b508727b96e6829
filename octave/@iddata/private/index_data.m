## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{dat} =} index_data (@var{dat}, @var{idx})
## @code{dat(samples, outputs, inputs, experiments)}: select samples and
## channels of an @code{iddata} set.  @var{idx} is the cell of up to four
## subscripts; channels and experiments may also be selected by name.
##
## The sample indices must increase.  Sampling instants of irregular
## experiments are selected with the samples.  For a regularly sampled
## experiment, a selection with a constant step k gives sampling interval
## k*Ts (and starts again at time 0); an uneven selection keeps the
## selected instants @code{(i-1)*Ts} as irregular sampling instants.
## The @code{userdata} field, hence @code{InterSample}, is kept.
## @end deftypefn

function dat = index_data (dat, idx)
  if (numel (idx) > 4)
    error ("iddata:badInput",
           "iddata: index as data(samples, outputs, inputs, experiments)");
  endif
  idx(end+1:4) = {":"};
  [spl, out_idx, in_idx, exp_idx] = idx{:};
  exp_idx = channel_index (dat.expname, exp_idx, "experiment");
  out_idx = channel_index (dat.outname, out_idx, "output");
  in_idx = channel_index (dat.inname, in_idx, "input");

  dat.y = dat.y(exp_idx);
  dat.expname = dat.expname(exp_idx);
  dat.tsam = dat.tsam(exp_idx);
  if (! isempty (dat.u))
    dat.u = dat.u(exp_idx);
  endif
  nexp = numel (dat.y);
  if (isempty (dat.w))
    w = cell (nexp, 1);
  else
    w = dat.w(exp_idx);
  endif

  for k = 1:nexp
    n = rows (dat.y{k});
    keep = sample_index (spl, n, k);
    dat.y{k} = dat.y{k}(keep, out_idx);
    if (! isempty (dat.u))
      dat.u{k} = dat.u{k}(keep, in_idx);
    endif
    if (! isempty (w{k}))
      w{k} = w{k}(keep);
    elseif (dat.timedomain && dat.tsam{k} > 0 && ! isequal (keep, 1:n))
      step = unique (diff (keep));
      if (isscalar (step))
        dat.tsam{k} *= step;
      elseif (! isempty (step))
        w{k} = (keep(:) - 1) * dat.tsam{k};
        dat.tsam{k} = -1;
      endif
    endif
  endfor

  dat.outname = dat.outname(out_idx);
  dat.outunit = dat.outunit(out_idx);
  dat.inname = dat.inname(in_idx);
  dat.inunit = dat.inunit(in_idx);
  if (dat.timedomain && all (cellfun ("isempty", w)))
    dat.w = {};
  else
    dat.w = w;
  endif
endfunction

function keep = sample_index (spl, n, k)
  if (ischar (spl) && strcmp (spl, ":"))
    keep = 1:n;
    return;
  endif
  if (islogical (spl))
    if (numel (spl) > n)
      error ("iddata:badInput",
             "iddata: logical sample index longer than the %d samples", n);
    endif
    keep = find (spl(:).');
  elseif (isnumeric (spl) && isreal (spl)
          && all (spl(:) >= 1 & spl(:) <= n & spl(:) == fix (spl(:))))
    keep = double (spl(:).');
  else
    error ("iddata:badInput",
           "iddata: sample index must be integers from 1 to %d (experiment %d)",
           n, k);
  endif
  if (any (diff (keep) <= 0))
    error ("iddata:badInput", "iddata: sample indices must increase");
  endif
endfunction

function idx = channel_index (names, idx, what)
  n = numel (names);
  if (ischar (idx) && strcmp (idx, ":"))
    idx = 1:n;
    return;
  endif
  if (ischar (idx))
    idx = {idx};
  endif
  if (iscellstr (idx))
    idx = cellfun (@(name) name_index (names, name, what), idx);
  elseif (islogical (idx) && numel (idx) <= n)
    idx = find (idx);
  elseif (! (isnumeric (idx) && isreal (idx)
             && all (idx(:) >= 1 & idx(:) <= n & idx(:) == fix (idx(:)))))
    error ("iddata:badInput",
           "iddata: %s index must be integers from 1 to %d or names",
           what, n);
  endif
  idx = idx(:).';
endfunction

function k = name_index (names, name, what)
  k = find (strcmp (names, name));
  if (numel (k) != 1)
    error ("iddata:badInput",
           "iddata: %s name '%s' matches %d %ss, not one",
           what, name, numel (k), what);
  endif
endfunction

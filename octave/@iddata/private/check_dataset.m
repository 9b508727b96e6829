## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {} check_dataset (@var{dat}, @var{who})
## Check that the fields of @var{dat} agree with each other: the same number
## of samples in @code{y}, @code{u} and the sampling instants (or
## frequencies) of each experiment, the same channels in every experiment,
## and real signals in a time-domain set.  @var{who} starts the messages.
## @end deftypefn

function check_dataset (dat, who)
  nexp = numel (dat.y);
  ny = cellfun ("rows", dat.y);
  if (nexp > 1 && any (cellfun ("columns", dat.y) != columns (dat.y{1})))
    error ("iddata:dimensionMismatch",
           "%s: every experiment of 'y' must have the same outputs", who);
  endif
  if (! isempty (dat.u))
    if (numel (dat.u) != nexp)
      error ("iddata:dimensionMismatch",
             "%s: 'y' has %d experiments but 'u' has %d", who, nexp,
             numel (dat.u));
    endif
    if (nexp > 1 && any (cellfun ("columns", dat.u) != columns (dat.u{1})))
      error ("iddata:dimensionMismatch",
             "%s: every experiment of 'u' must have the same inputs", who);
    endif
    nu = cellfun ("rows", dat.u);
    k = find (nu != ny, 1);
    if (! isempty (k))
      error ("iddata:dimensionMismatch",
             "%s: 'y' has %d samples but 'u' has %d (experiment %d)",
             who, ny(k), nu(k), k);
    endif
  endif
  if (! isempty (dat.w))
    nw = cellfun ("numel", dat.w(:));
    if (dat.timedomain)
      k = find (nw != ny & nw != 0, 1);
      what = "sampling instants";
    else
      k = find (nw != ny, 1);
      what = "frequencies";
    endif
    if (! isempty (k))
      error ("iddata:dimensionMismatch",
             "%s: experiment %d has %d samples but %d %s",
             who, k, ny(k), nw(k), what);
    endif
  endif
  if (dat.timedomain && ! (all (cellfun ("isreal", dat.y))
                           && all (cellfun ("isreal", dat.u))))
    error ("iddata:badInput",
           "%s: the signals 'y' and 'u' of time-domain data must be real",
           who);
  endif
endfunction

## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{dat} =} concat_sets (@var{dim}, @var{sets}, @var{who})
## Join the @code{iddata} sets in the cell @var{sets}: along the samples
## (@var{dim} 1, @code{[d1; d2]}), the channels (2, @code{[d1, d2]}) or the
## experiments (3, @code{merge}).  Empty numeric entries (@code{[]}, as in
## @code{data = [data; d]} in a loop) are skipped.  @var{who} starts the
## messages.
##
## What cannot be joined is an identified error, never a silent change:
## @itemize
## @item the sets must all be time-domain or all frequency-domain
## (@code{iddata:badInput});
## @item one @code{InterSample} for the result: the sets that have inputs
## must agree on it (@code{iddata:notSupported} otherwise); output-only sets
## take any;
## @item samples (1): equal numbers of experiments and channels
## (@code{iddata:dimensionMismatch}); per experiment either the same
## sampling interval (the result stays regular) or sampling instants of
## each later set that all follow those of the earlier ones (the result is
## irregular, with the joined instants); two regular sets with different
## intervals, or instants that do not increase, are @code{iddata:badInput};
## frequency-domain sets join their frequencies the same way;
## @item channels (2): equal numbers of experiments and samples
## (@code{iddata:dimensionMismatch}) and the same sampling (intervals,
## instants or frequencies; @code{iddata:badInput});
## @item experiments (3): equal numbers of channels
## (@code{iddata:dimensionMismatch}); each experiment keeps its own
## sampling interval or instants.
## @end itemize
## The channel names, units and user data of the first set are kept
## (for channels, the names of every set in order).  An error is also
## issued as a warning with its identifier and message just before, since
## Octave 7 reports errors from the concatenation operator
## (@code{[d1; d2]}) only as @qcode{"iddata/vertcat method failed"}.
## @end deftypefn

function dat = concat_sets (dim, sets, who)
  try
    dat = join_sets (dim, sets, who);
  catch err
    ## Octave 7 replaces the message and identifier of an error raised in
    ## a concatenation method called by the operator ([d1; d2]) with
    ## "iddata/vertcat method failed": say the reason as a warning first
    if (strncmp (err.identifier, "iddata:", 7))
      warning ("off", "backtrace", "local");
      warning (err.identifier, "%s", err.message);
    endif
    rethrow (err);
  end_try_catch
endfunction

function dat = join_sets (dim, sets, who)
  sets = sets(! cellfun (@(s) isnumeric (s) && isempty (s), sets));
  if (isempty (sets))
    dat = iddata ();
    return;
  endif
  bad = find (! cellfun (@(s) isa (s, "iddata"), sets), 1);
  if (! isempty (bad))
    error ("iddata:badInput",
           "%s: argument %d is a %s, not an iddata set", who, bad,
           class (sets{bad}));
  endif
  s = cellfun (@struct, sets);
  if (numel (s) == 1)
    dat = sets{1};
    return;
  endif
  if (! all ([s.timedomain] == s(1).timedomain))
    error ("iddata:badInput",
           "%s: cannot join time-domain and frequency-domain sets", who);
  endif
  timedomain = s(1).timedomain;
  nexp = arrayfun (@(x) numel (x.y), s);
  ny = arrayfun (@(x) numel (x.outname), s);
  nu = arrayfun (@(x) numel (x.inname), s);
  intersample = common_intersample (s, nu, who);

  out = s(1);
  switch (dim)
    case 1
      same_count (nexp, "experiments", who);
      same_count (ny, "outputs", who);
      same_count (nu, "inputs", who);
      [tsam, w] = sampling (s(1));
      for k = 2:numel (s)
        [tsam_k, w_k] = sampling (s(k));
        for e = 1:nexp(1)
          [tsam{e}, w{e}] = join_sampling (tsam{e}, w{e}, rows (out.y{e}),
                                           tsam_k{e}, w_k{e},
                                           rows (s(k).y{e}), timedomain,
                                           e, k, who);
          out.y{e} = [out.y{e}; s(k).y{e}];
          if (nu(1) > 0)
            out.u{e} = [out.u{e}; s(k).u{e}];
          endif
        endfor
      endfor
      out.tsam = tsam;
      out.w = pack_w (w, timedomain);
    case 2
      same_count (nexp, "experiments", who);
      n1 = cellfun ("rows", s(1).y(:));
      [tsam, w] = sampling (s(1));
      for k = 2:numel (s)
        if (! isequal (cellfun ("rows", s(k).y(:)), n1))
          error ("iddata:dimensionMismatch",
                 "%s: set %d has not the same numbers of samples as set 1",
                 who, k);
        endif
        [tsam_k, w_k] = sampling (s(k));
        if (! (isequal (tsam_k, tsam) && isequal (w_k, w)))
          error ("iddata:badInput",
                 ["%s: set %d is not sampled as set 1 (sampling interval, ", ...
                  "instants or frequencies differ)"], who, k);
        endif
      endfor
      for e = 1:nexp(1)
        out.y{e} = cell2mat (arrayfun (@(x) x.y{e}, s, "uniformoutput",
                                       false)(:).');
      endfor
      withu = find (nu > 0);
      if (isempty (withu))
        out.u = {};
      else
        out.u = cell (nexp(1), 1);
        for e = 1:nexp(1)
          out.u{e} = cell2mat (arrayfun (@(x) x.u{e}, s(withu),
                                         "uniformoutput", false)(:).');
        endfor
      endif
      out.outname = vertcat (s.outname);
      out.outunit = vertcat (s.outunit);
      out.inname = vertcat (s.inname);
      out.inunit = vertcat (s.inunit);
    case 3
      same_count (ny, "outputs", who);
      same_count (nu, "inputs", who);
      out.y = vertcat (s.y);
      if (nu(1) > 0)
        out.u = vertcat (s.u);
      endif
      out.tsam = vertcat (s.tsam);
      out.expname = vertcat (s.expname);
      w = {};
      for k = 1:numel (s)
        [~, w_k] = sampling (s(k));
        w = [w; w_k];
      endfor
      out.w = pack_w (w, timedomain);
    otherwise
      error ("iddata:badInput",
             ["%s: dimension must be 1 (samples), 2 (channels) or 3 ", ...
              "(experiments)"], who);
  endswitch
  [user, ~] = unpack_userdata (s(1).userdata);
  given = arrayfun (@(x) nthargout (3, @unpack_userdata, x.userdata), s);
  out.userdata = pack_userdata (user, intersample, any (given));
  dat = sets{1};
  for [val, key] = out
    dat.(key) = val;
  endfor
  check_dataset (dat, who);
endfunction

function is = common_intersample (s, nu, who)
  all_is = arrayfun (@(x) nthargout (2, @unpack_userdata, x.userdata), s,
                     "uniformoutput", false);
  withu = all_is(nu > 0);
  if (isempty (withu))
    is = all_is{1};
  else
    is = withu{1};
    if (! all (strcmp (withu, is)))
      error ("iddata:notSupported",
             ["%s: the sets have different InterSample (%s); a set has ", ...
              "one for all its inputs: set it equal first"],
             who, strjoin (unique (withu), ", "));
    endif
  endif
endfunction

function same_count (n, what, who)
  if (any (n != n(1)))
    error ("iddata:dimensionMismatch",
           "%s: the sets have different numbers of %s (%s)", who, what,
           num2str (n));
  endif
endfunction

## per-experiment sampling interval and instants (or frequencies), w{e}
## empty for a regular time-domain experiment
function [tsam, w] = sampling (x)
  tsam = x.tsam(:);
  if (isempty (x.w))
    w = cell (numel (x.y), 1);
  else
    w = x.w(:);
  endif
endfunction

function w = pack_w (w, timedomain)
  if (timedomain && all (cellfun ("isempty", w)))
    w = {};
  endif
endfunction

function [ts, w] = join_sampling (ts, w, n, ts2, w2, n2, timedomain, e, k,
                                  who)
  if (timedomain && isempty (w) && isempty (w2))
    if (ts != ts2)
      error ("iddata:badInput",
             ["%s: set %d is sampled every %g, set 1 every %g ", ...
              "(experiment %d); join them with merge, or give sampling ", ...
              "instants"], who, k, ts2, ts, e);
    endif
    return;
  endif
  if (! timedomain && ts != ts2)
    error ("iddata:badInput",
           "%s: set %d has Ts = %g, set 1 Ts = %g (experiment %d)",
           who, k, ts2, ts, e);
  endif
  t1 = instants (ts, w, n, e, who);
  t2 = instants (ts2, w2, n2, e, who);
  if (n > 0 && n2 > 0 && t2(1) <= t1(end))
    if (timedomain)
      what = "sampling instants";
    else
      what = "frequencies";
    endif
    error ("iddata:badInput",
           ["%s: the %s of set %d (from %g) do not follow those before ", ...
            "(up to %g, experiment %d); shift them or use merge"],
           who, what, k, t2(1), t1(end), e);
  endif
  w = [t1; t2];
  if (timedomain)
    ts = -1;
  endif
endfunction

function t = instants (ts, w, n, e, who)
  if (! isempty (w) || n == 0)
    t = w(:);
  elseif (ts > 0)
    t = (0:n-1).' * ts;
  else
    error ("iddata:badInput",
           ["%s: experiment %d has no sampling interval; it cannot be ", ...
            "joined with irregularly sampled data"], who, e);
  endif
endfunction

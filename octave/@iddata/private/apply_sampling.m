## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn  {} {@var{dat} =} apply_sampling (@var{dat}, @var{val}, @
##   @var{key}, @var{who})
## @deftypefnx {} {@var{dat} =} apply_sampling (@dots{}, @var{who}, "instants")
## Set the sampling of every experiment of @var{dat} from @var{val}.
##
## @var{val} is @code{[]} or -1 (unspecified sampling interval), a positive
## scalar @var{Ts}, a vector of sampling instants (one per sample), or a
## cell with one such entry per experiment (a single entry applies to all).
## A scalar sampling interval goes to @code{tsam} (0, continuous time, only
## for frequency-domain data); sampling instants go to
## @code{w} (one column per experiment, @code{[]} for the regularly sampled
## ones) and set @code{tsam} to -1.  @code{w} stays @code{@{@}} when no
## experiment is irregular, as in control-package objects.
##
## With @qcode{"instants"} (the @qcode{"SamplingInstants"} property) every
## non-empty entry is a vector of instants and an empty entry drops the
## instants of that experiment.
## @end deftypefn

function dat = apply_sampling (dat, val, key, who, mode = "")
  instants_only = strcmp (mode, "instants");
  nexp = numel (dat.y);
  nsamples = cellfun ("rows", dat.y);

  if (iscell (val))
    if (numel (val) == 1)
      val = repmat (val, nexp, 1);
    elseif (numel (val) != nexp)
      error ("iddata:dimensionMismatch",
             "%s: '%s' has %d entries but the data set has %d experiments",
             who, key, numel (val), nexp);
    endif
    spec = val(:);
  elseif (isempty (val) || isscalar (val) && ! instants_only)
    spec = repmat ({val}, nexp, 1);
  elseif (isvector (val) && nexp == 1)
    spec = {val};
  else
    error ("iddata:badInput",
           ["%s: '%s' of a multi-experiment data set must be a scalar ", ...
            "or a cell with one entry per experiment"], who, key);
  endif

  if (isempty (dat.w) || ! dat.timedomain)
    w = cell (nexp, 1);
  else
    w = dat.w(:);
  endif
  tsam = dat.tsam(:);
  for k = 1:nexp
    v = spec{k};
    if (! ((isnumeric (v) && isreal (v)) || isempty (v)))
      error ("iddata:badInput", "%s: '%s' must be real and numeric",
             who, key);
    endif
    if (isempty (v))
      w{k} = [];
      if (! instants_only)
        tsam{k} = -1;
      endif
    elseif (isscalar (v) && ! instants_only)
      if (! (v == -1 || (v > 0 && isfinite (v))
             || (v == 0 && ! dat.timedomain)))
        error ("iddata:badInput",
               ["%s: '%s' must be a positive finite sampling interval ", ...
                "(or -1 when unspecified; 0 only for continuous-time ", ...
                "frequency-domain data)"], who, key);
      endif
      tsam{k} = double (v);
      w{k} = [];
    else
      if (! dat.timedomain)
        error ("iddata:badInput",
               "%s: '%s': a frequency-domain data set has no sampling instants",
               who, key);
      endif
      if (! isvector (v) || numel (v) != nsamples(k))
        error ("iddata:dimensionMismatch",
               ["%s: '%s' has %d sampling instants but experiment %d has ", ...
                "%d samples"], who, key, numel (v), k, nsamples(k));
      endif
      if (! all (isfinite (v)) || any (diff (v) <= 0))
        error ("iddata:badInput",
               "%s: sampling instants '%s' must be finite and increasing",
               who, key);
      endif
      tsam{k} = -1;
      w{k} = double (v(:));
    endif
  endfor

  dat.tsam = tsam;
  if (dat.timedomain)
    if (all (cellfun ("isempty", w)))
      dat.w = {};
    else
      dat.w = w;
    endif
  endif
endfunction

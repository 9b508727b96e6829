## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {[@var{sys}, @var{iu}, @var{extra}] =} pre_lti_args @
##   (@var{who}, @var{args})
## Read the pre-LTI (numeric) argument forms of @code{step} and @code{bode}:
## @code{(num, den[, extra])} gives the continuous-time @code{tf (num, den)},
## @code{(a, b, c, d[, iu[, extra]])} the continuous-time
## @code{ss (a, b, c, d)} and the input index @var{iu} (@code{[]}: all
## inputs).  @var{extra} is the time or frequency argument (@code{[]} when
## absent).  Every other numeric form is an error
## @code{@var{who}:badInput}: the control package never accepts these
## forms, so nothing it accepts is read here.
## @end deftypefn

function [sys, iu, extra] = pre_lti_args (who, args)
  if (exist ("tf") != 2 && exist ("tf") != 3)
    error ([who, ":notSupported"],
           "%s: the numeric forms need the control package (pkg load control)",
           who);
  endif
  bad = find (! cellfun (@is_real_matrix, args), 1);
  if (! isempty (bad))
    error ([who, ":badInput"],
           "%s: argument %d of the numeric form must be a real matrix",
           who, bad);
  endif
  ## full: the control package takes a sparse time or frequency argument
  ## for something else and fails without an identifier.
  args = cellfun (@(x) full (double (x)), args, "uniformoutput", false);
  nsys = 2 + 2 * (numel (args) >= 4);    # num, den or a, b, c, d
  bad = find (! cellfun (@(x) all (isfinite (x(:))),
                         args(1:min (nsys, end))), 1);
  if (! isempty (bad))
    error ([who, ":badInput"],
           "%s: argument %d of the numeric form must be finite", who, bad);
  endif
  iu = [];
  extra = [];
  switch (numel (args))
    case {2, 3}
      [num, den] = args{1:2};
      if (! (isvector (den) && any (den != 0) && (isvector (num)
                                                  || isempty (num))))
        error ([who, ":badInput"],
               "%s: %s (num, den): 'num' and 'den' must be coefficient rows",
               who, who);
      endif
      sys = tf (num(:).', den(:).');
      if (numel (args) == 3)
        extra = args{3};
      endif
    case {4, 5, 6}
      [a, b, c, d] = args{1:4};
      n = rows (a);
      if (columns (a) != n || rows (b) != n || columns (c) != n
          || ! isequal (size (d), [rows(c), columns(b)]))
        error ([who, ":dimensionMismatch"],
               "%s: %s (a, b, c, d): the matrix sizes do not agree", who, who);
      endif
      sys = ss (a, b, c, d);
      if (numel (args) >= 5)
        iu = args{5};
        if (! isempty (iu) && ! (isscalar (iu) && iu >= 1
                                 && iu <= columns (b) && iu == fix (iu)))
          error ([who, ":badInput"],
                 "%s: 'iu' must be an input index from 1 to %d", who,
                 columns (b));
        endif
      endif
      if (numel (args) == 6)
        extra = args{6};
      endif
    otherwise
      error ([who, ":badInput"],
             ["%s: with numeric arguments use %s (num, den[, t]) or ", ...
              "%s (a, b, c, d[, iu[, t]])"], who, who, who);
  endswitch
  if (! isempty (extra) && ! (isvector (extra) && all (isfinite (extra))))
    error ([who, ":badInput"], "%s: the last argument must be a vector", who);
  endif
  ## The time (final time or instants) or the frequencies: positive, and
  ## increasing when a vector (the control package rejects the rest
  ## without an identifier).
  if (! isempty (extra) && (any (extra(:) < 0) || (isscalar (extra)
                                                   && extra <= 0)
                            || any (diff (extra(:)) <= 0)))
    error ([who, ":badInput"],
           "%s: the time or frequency argument must be positive and increasing",
           who);
  endif
  ## A step response needs a proper model (the control package's
  ## conversion of an improper one fails under its own identifier).
  if (strcmp (who, "step") && isa (sys, "tf"))
    [n, d] = tfdata (sys, "vector");
    if (numel (n) - find (n != 0, 1) > numel (d) - find (d != 0, 1))
      error ([who, ":badInput"],
             "%s: num/den is improper (more zeros than poles)", who);
    endif
    if (numel (d) - find (d != 0, 1) == 0)
      ## (the control package's step fails on it without an identifier)
      error ([who, ":notSupported"],
             "%s: num/den is a static gain: its step response is num/den",
             who);
    endif
  endif
endfunction

function ok = is_real_matrix (x)
  ok = (isnumeric (x) || islogical (x)) && isreal (x) && ismatrix (x);
endfunction

## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {[@var{pos}, @var{pairs}, @var{Ts}] =} @
##   ctor_args (@var{cls}, @var{args}, @var{npos})
## Splits the arguments @var{args} of the constructor of class @var{cls}
## (@code{idpoly}, @code{idtf}, @code{idss}) into positional arguments,
## all before the first string, and name-value pairs.  There must be
## @var{npos}(1) to @var{npos}(2) positional ones; @var{pos} is padded
## with @code{[]} to @var{npos}(2).  A @code{Ts} pair (the last one
## given) is taken out of @var{pairs} and returned in @var{Ts} (@code{[]}
## without one), since it decides how the other properties are read.
## Errors: @code{@var{cls}:badInput}.  Linked into the private folders of
## the constructors, which cannot see this one.
## @end deftypefn

function [pos, pairs, Ts] = ctor_args (cls, args, npos)
  n = find (cellfun ("ischar", args), 1) - 1;
  if (isempty (n))
    n = numel (args);
  endif
  if (n < npos(1) || n > npos(2))
    error ([cls ":badInput"], "%s: expected %d to %d leading arguments",
           cls, npos(1), npos(2));
  endif
  pos = [args(1:n), cell(1, npos(2) - n)];
  pairs = args(n+1:end);
  if (mod (numel (pairs), 2) != 0)
    error ([cls ":badInput"],
           "%s: properties must come in name-value pairs", cls);
  endif
  Ts = [];
  k = find (strcmpi (pairs(1:2:end), "Ts"), 1, "last");
  if (! isempty (k))
    Ts = pairs{2*k};
    pairs(2*k-1:2*k) = [];
  endif
endfunction

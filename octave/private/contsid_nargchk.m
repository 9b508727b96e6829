## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {} contsid_nargchk (@var{fname}, @var{nin}, @var{nout}, @
##   @var{inrange}, @var{maxout})
## Check the number of arguments of the public function @var{fname}:
## @var{nin} (its @code{nargin}) must lie in @var{inrange} = [min max]
## (@code{Inf} for no maximum) and @var{nout} (its @code{nargout}) must
## not exceed @var{maxout}.  Errors with identifier
## @code{@var{fname}:badInput} and a message starting with @var{fname}.
##
## A public function declares a trailing @code{varargout} (and
## @code{varargin}) so that Octave lets the call through to this check
## instead of raising its own @code{Octave:invalid-fun-call}:
## @example
## function [M, RT2, varargout] = f (varargin)
##   contsid_nargchk ("f", nargin, nargout, [2 Inf], 2);
## @end example
## @end deftypefn

function contsid_nargchk (fname, nin, nout, inrange, maxout)
  if (nin < inrange(1))
    error ([fname ":badInput"],
           "%s: called with %d arguments, needs at least %d", fname, nin,
           inrange(1));
  endif
  if (nin > inrange(2))
    error ([fname ":badInput"],
           "%s: called with %d arguments, takes at most %d", fname, nin,
           inrange(2));
  endif
  if (nout > maxout)
    error ([fname ":badInput"],
           "%s: called with %d outputs, returns at most %d", fname, nout,
           maxout);
  endif
endfunction

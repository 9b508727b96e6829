## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn  {} {@var{s} =} get (@var{M})
## @deftypefnx {} {@var{v} =} get (@var{M}, @var{name})
## The fields of a model @code{residtrace} returned (see
## @code{help idtraced}): all of them as a struct @var{s} (which
## @code{idtraced (@var{s})} turns back into the model), or the one named
## @var{name}, as @code{M.name}. An unknown name is
## @code{idtraced:badInput}.
##
## @strong{Example}
## @example
## Ts = 0.05; u = prbs (9, 4); N = numel (u); G = idctm (2, [1 1.2 1]);
## y = simc (G, u + 0.3, Ts) + 0.03 * randn (N, 1);
## R = residtrace (iddata (y, u, Ts), G, "effects", @{"offset"@});
## fieldnames (get (R.final_model))
## get (R.final_model, "u0")
## @end example
## @end deftypefn

function varargout = get (varargin)
  varargout = contsid_guard ({"get", "idtraced"}, @get_body, nargout,
                             varargin);
endfunction

function [v, varargout] = get_body (M, varargin)
  contsid_nargchk ("get", nargin, nargout, [1 2], 1);
  P = struct (M).model;
  if (nargin == 1)
    v = P;
    return;
  endif
  name = varargin{1};
  if (! ischar (name) || ! isfield (P, name))
    error ("idtraced:badInput", "idtraced: no such field (fields: %s)",
           strjoin (fieldnames (P).', ", "));
  endif
  v = P.(name);
endfunction

%!test
%! s = struct ("F", [1 1], "channels", struct ("type", "input", "B", 1),
%!             "out", struct ("type", {}), "u0", 2, "Ts", 0.1, "npre", 0,
%!             "substeps", 10, "closed_loop", false, "params", [],
%!             "linear", idctm (1, [1 1]));
%! M = idtraced (s);
%! g = get (M);
%! assert (fieldnames (g), fieldnames (s));
%! assert (rmfield (g, "linear"), rmfield (s, "linear"));
%! assert (get (M, "u0"), 2);
%! assert (get (idtraced (get (M)), "F"), [1 1]);

%!error id=idtraced:badInput get (idtraced (), "F")
%!error id=idtraced:badInput get (idtraced (), 1)

## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{v} =} subsref (@var{M}, @var{s})
## @code{M.name} reads a field of a model @code{residtrace} returned
## (@code{M.linear}, @code{M.F}, @code{M.channels}, @code{M.params},
## @code{M.u0}, ...: see @code{help idtraced} and @code{get (M)}); the
## rest of the index applies to the field (@code{M.channels(2).type},
## @code{M.linear.F}). A name that is not a field, or @code{M(...)},
## @code{M@{...@}}, is @code{idtraced:badInput}, and so is an index that
## would give a list of several values (@code{@{M.params.name@}}: Octave
## does not let an object's index return a list; read the field first,
## @code{p = M.params; @{p.name@}}).
##
## @strong{Example}
## @example
## Ts = 0.05; u = prbs (9, 4); N = numel (u); G = idctm (2, [1 1.2 1]);
## y = simc (G, u + 0.3, Ts) + 0.03 * randn (N, 1);
## R = residtrace (iddata (y, u, Ts), G, "effects", @{"offset"@});
## R.final_model.linear            # the linear part, an idpoly
## p = R.final_model.params; @{p.name@}   # the physical parameters' names
## @end example
## @end deftypefn

function varargout = subsref (M, s, varargin)
  contsid_nargchk ("subsref", nargin, 0, [2 2], 0);
  if (! isa (M, "idtraced") || ! isstruct (s) || ! isfield (s, "type")
      || ! isfield (s, "subs") || isempty (s) || ! ischar (s(1).type)
      || ! strcmp (s(1).type, ".") || ! ischar (s(1).subs))
    error ("idtraced:badInput",
           "idtraced: use M.name (see get (M) for the names)");
  endif
  P = struct (M).model;
  name = s(1).subs;
  if (! isfield (P, name))
    error ("idtraced:badInput", "idtraced: no field '%s' (fields: %s)", name,
           strjoin (fieldnames (P).', ", "));
  endif
  v = P.(name);
  if (numel (s) == 1)
    if (nargout > 1)
      error ("idtraced:badInput", "idtraced: M.%s is one value", name);
    endif
    varargout = {v};
    return;
  endif
  try
    n = 1;
    if (strcmp (s(end).type, "."))
      w = v;
      if (numel (s) > 2)
        w = subsref (v, s(2:end-1));
      endif
      if (isstruct (w))
        n = numel (w);
      endif
    endif
    if (n > max (nargout, 1))
      error ("M.%s: a list of %d values; take M.%s first", name, n, name);
    endif
    [varargout{1:max (nargout, 1)}] = subsref (v, s(2:end));
  catch err
    error ("idtraced:badInput", "idtraced: %s", err.message);
  end_try_catch
endfunction

%!shared M
%! ch = struct ("type", {"input", "const"}, "B", {1, 0.5});
%! s = struct ("F", [1 1], "channels", ch, "out", struct ("type", {}),
%!             "u0", 2, "Ts", 0.1, "npre", 0, "substeps", 10,
%!             "closed_loop", false,
%!             "params", struct ("name", {"a", "b"}, "value", {1, 2},
%!                               "std", {0.1, NaN}),
%!             "linear", idctm (1, [1 1]));
%! M = idtraced (s);

%!test
%! assert (M.u0, 2);
%! assert (M.channels(2).type, "const");
%! ch = M.channels;
%! assert ({ch.type}, {"input", "const"});
%! assert (M.params(2).value, 2);
%! assert (M.linear.F, [1 1]);

%!error id=idtraced:badInput M.nothing
%!error id=idtraced:badInput M(1)
%!error id=idtraced:badInput M.channels(3)
%!error <a list of 2 values> x = {M.channels.type}

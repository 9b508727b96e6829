## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{M} =} subsasgn (@var{M}, @var{s}, @var{v})
## @code{M.Property = value} sets a property of a model, with the checks
## of @code{set}; nested assignments such as
## @code{init_sys.Structure.Td.Value = 0.5} or @code{M.B(2) = 3} work.
## @end deftypefn

function [M, varargout] = subsasgn (M, s, v, varargin)
  contsid_nargchk ("subsasgn", nargin, nargout, [3 3], 1);
  P = pstruct (M);
  check_subs (s, P.kind);
  if (! strcmp (s(1).type, "."))
    error ([P.kind ":notSupported"],
           "%s: use M.Property = value; indexed assignment is not supported",
           P.kind);
  endif
  name = match_prop (P, s(1).subs, P.kind);
  if (numel (s) > 1)
    try
      v = subsasgn (get_prop (P, name), s(2:end), v);
    catch err
      error ([P.kind ":badInput"], "%s: %s", P.kind, err.message);
    end_try_catch
  endif
  P = set_prop (P, name, v, P.kind);
  for f = fieldnames (P).'
    M.(f{1}) = P.(f{1});
  endfor
endfunction

%!test
%! M = idpoly (1, 2, 1, 1, [1 1.2 2], "Ts", 0);
%! M.B = 3;
%! assert (M.B, 3);
%! M.F(3) = 4;
%! assert (M.F, [1 1.2 4]);
%! P = idproc ("P2DU");
%! P.Structure.Td.Value = 0.5;
%! assert (P.Td, 0.5);
%! P.Kp = 2;
%! assert (P.Structure.Kp.Value, 2);
%!error id=idpoly:badInput M = idpoly (1, 2, 1, 1, [1 1]); M.F = [2 1];
%!error id=idpoly:badInput M = idpoly (1, 2, 1, 1, [1 1]); M.InputDelay = -1;
%!error id=idpoly:badInput M = idpoly (1, 2, 1, 1, [1 1]); M.bogus = 1;
%!error id=idpoly:notSupported M = idpoly (1, 2, 1, 1, [1 1]); M(1) = 1;
%!error id=idproc:badInput P = idproc ("P1D"); P.Td = -1;

%!demo
%! init_sys = idproc ("P2DU");
%! init_sys.Structure.Td.Value = 0.2;
%! init_sys.Structure.Td.Maximum = 1;
%! init_sys

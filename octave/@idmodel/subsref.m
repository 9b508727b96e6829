## -*- texinfo -*-
## @deftypefn {} {@var{v} =} subsref (@var{M}, @var{s})
## @code{M.Property} reads a property of a model (@code{idpoly},
## @code{idtf}, @code{idproc}, @code{idss}, @code{idfrd}); names are
## case-insensitive and unique prefixes are accepted, as in the System
## Identification Toolbox (@code{M.b}, @code{init_sys.structure.Td.Value}).
## See @code{get (M)} for the list.
## @end deftypefn

function [v, varargout] = subsref (M, s, varargin)
  contsid_nargchk ("subsref", nargin, nargout, [2 2], 1);
  P = pstruct (M);
  check_subs (s, P.kind);
  if (! strcmp (s(1).type, "."))
    error ([P.kind ":notSupported"],
           "%s: use M.Property to read a model; indexing is not supported",
           P.kind);
  endif
  v = get_prop (P, match_prop (P, s(1).subs, P.kind));
  if (numel (s) > 1)
    v = nested_ref (v, s(2:end), P.kind);
  endif
endfunction

## The rest of M.Property(...)...: Octave's own indexing errors become
## identified ones.
function v = nested_ref (v, s, kind)
  try
    v = subsref (v, s);
  catch err
    error ([kind ":badInput"], "%s: %s", kind, err.message);
  end_try_catch
endfunction

%!test
%! M = idpoly (1, [0 2], 1, 1, [1 1.2 2], "Ts", 0);
%! assert (M.B, [0 2]);
%! assert (M.b(2), 2);
%! assert (M.f, [1 1.2 2]);
%! P = idproc ("P2DU");
%! assert (isnan (P.structure.Td.Value));
%!error id=idpoly:badInput idpoly (1, 2, 1, 1, [1 1], "Ts", 0).nothing
%!error id=idpoly:notSupported subsref (idpoly (1, 2, 1, 1, [1 1], "Ts", 0), struct ("type", "()", "subs", {{1}}))

%!demo
%! M0 = idpoly (1, [1 4], 1, 1, [1 2.4 4], "Ts", 0);
%! B = M0.B, F = M0.F, fit = M0.Report.Fit.FitPercent

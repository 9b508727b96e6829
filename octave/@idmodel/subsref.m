## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn  {} {@var{v} =} subsref (@var{M}, @var{s})
## @deftypefnx {} {@var{Ms} =} M(@var{i}, @var{j})
## @code{M.Property} reads a property of a model (@code{idpoly},
## @code{idtf}, @code{idproc}, @code{idss}, @code{idfrd}); names are
## case-insensitive and unique prefixes are accepted, as in the System
## Identification Toolbox (@code{M.b}, @code{init_sys.structure.Td.Value}).
## See @code{get (M)} for the list.  @code{M(i, j)} selects the channels
## from the inputs @var{j} to the outputs @var{i} (SITB semantics: delays,
## names and the noise variance of those channels come along; the
## parameter covariance does not).
## @end deftypefn

function [v, varargout] = subsref (M, s, varargin)
  contsid_nargchk ("subsref", nargin, nargout, [2 2], 1);
  P = pstruct (M);
  check_subs (s, P.kind);
  switch (s(1).type)
    case "."
      v = get_prop (P, match_prop (P, s(1).subs, P.kind));
    case "()"
      v = select_channels (M, P, s(1).subs);
    otherwise
      error ([P.kind ":notSupported"],
             "%s: use M.Property or M(outputs, inputs); not M{...}", P.kind);
  endswitch
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
%!error id=idpoly:notSupported
%! subsref (idpoly (1, 2, 1, 1, [1 1], "Ts", 0),
%!          struct ("type", "{}", "subs", {{1}}))
%!error id=idpoly:badInput
%! subsref (idpoly (1, 2, 1, 1, [1 1], "Ts", 0),
%!          struct ("type", "()", "subs", {{1}}))
%!error id=idtf:badInput idtf ({1, 2}, {[1 1], [1 2]})(1, 3)
%!error id=idtf:badInput idtf ({1, 2}, {[1 1], [1 2]})(1, [])

%!test  # M(i, j) against the control package's channel selection
%! pkg load control
%! num = {1, [1 2]; 3, 4}; den = {[1 1], [1 3 2]; [1 5], [1 2 2]};
%! M = idtf (num, den, "IODelay", [0 0.1; 0.2 0.3], "InputName", {"a"; "b"});
%! G = tf (num, den);
%! w = logspace (-1, 1, 7);
%! M21 = M(2, 1);
%! assert (squeeze (freqresp (M21, w)),
%!         squeeze (freqresp (G(2, 1), w)) .* exp (-0.2i * w(:)), 1e-12);
%! assert ({M21.IODelay, M21.InputName}, {0.2, {"a"}});
%! assert (squeeze (freqresp (M(:, 2), w)),
%!         squeeze (freqresp (G(:, 2), w)) .* exp (-1i * [0.1; 0.3] * w),
%!         1e-12);
%! S = idss ([-1 0; 1 -2], [1 0; 0 1], [0 1; 1 1], [0 0; 0 0.5]);
%! Gs = ss ([-1 0; 1 -2], [1 0; 0 1], [0 1; 1 1], [0 0; 0 0.5]);
%! assert (freqresp (S(2, [false true]), w), freqresp (Gs(2, 2), w), 1e-12);
%! P = idpoly (1, {2, [1 1]}, 1, 1, {[1 3], [1 4 4]}, 0, 0,
%!             "InputDelay", [0.1; 0.2]);
%! P2 = P(1, 2);
%! assert ({P2.B, P2.F, P2.InputDelay}, {[1 1], [1 4 4], 0.2});
%! assert (P(1, :).B, P.B);
%! Fr = idfrd (freqresp (G, w), w, "Ts", 0);
%! assert (squeeze (Fr(1, 2).ResponseData), squeeze (freqresp (G(1, 2), w)),
%!         1e-14);

%!demo
%! M0 = idpoly (1, [1 4], 1, 1, [1 2.4 4], "Ts", 0);
%! B = M0.B, F = M0.F, fit = M0.Report.Fit.FitPercent

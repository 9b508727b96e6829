## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn  {} {@var{s} =} contsid_fit_status (@var{info})
## @deftypefnx {} {[@var{s}, @var{M}] =} contsid_fit_status (@var{info}, @var{M})
## The status of a refined-IV fit, made once from the engine's @var{info}
## and reported alike by every estimator of the family (@code{srivc},
## @code{rivc}, @code{clsrivc}, ...) and by @code{srivcstruc}: a struct
## with fields
## @table @code
## @item converged
## the iteration met its stopping rule;
## @item determined
## false when the data do not determine the structure (over-parameterised:
## a pole that died out within a sample, or whose time constant is not
## distinguished from 0, or the engine's own test); true when the engine
## says nothing;
## @item stable
## every pole of the model in the open left half-plane;
## @item reason
## the engine's words;
## @item text
## the three flags in words, e.g. @qcode{"converged, stable,
## over-parameterised"}.
## @end table
## With @var{M}, also written into the model: @code{Report.Termination}
## (@code{Converged}, @code{Determined}, @code{Stable}, @code{Reason}) and
## @code{Report.Status} (@qcode{"Estimated using SRIVC: converged,
## stable"}), which @code{present} shows.
## @end deftypefn

function [s, M] = contsid_fit_status (info, M)
  s.converged = logical (field (info, "converged", false));
  s.determined = logical (field (info, "determined", true));
  if (isfield (info, "stable"))
    s.stable = logical (info.stable);
  elseif (nargin > 1)
    s.stable = all (real (pole (M)) < 0);
  else
    s.stable = false;
  endif
  s.reason = field (info, "reason", "");
  words = {merge(s.converged, "converged", "not converged"), ...
           merge(s.stable, "stable", "unstable")};
  if (! s.determined)
    words{end+1} = "over-parameterised";
  endif
  s.text = strjoin (words, ", ");
  if (nargin > 1)
    r = get (M, "Report");
    r.Termination.Converged = s.converged;
    r.Termination.Determined = s.determined;
    r.Termination.Stable = s.stable;
    r.Termination.Reason = s.reason;
    if (! isempty (r.Method))
      r.Status = sprintf ("Estimated using %s: %s", upper (r.Method), s.text);
    endif
    M = set (M, "Report", r);
  endif
endfunction

function v = field (info, name, default)
  v = default;
  if (isfield (info, name) && ! isempty (info.(name)))
    v = info.(name);
  endif
endfunction

%!test
%! s = contsid_fit_status (struct ("converged", true, "stable", true,
%!                                 "determined", false, "reason", "r"));
%! assert (s.text, "converged, stable, over-parameterised");
%! assert ([s.converged, s.determined, s.stable], [true false true]);
%!test
%! M = idctm (struct ("B", 1, "F", [1 1], "method", "srivc"));
%! [s, M] = contsid_fit_status (struct ("converged", false, "reason", "x"),
%!                              M);
%! assert (s.stable);
%! assert (M.Report.Status, "Estimated using SRIVC: not converged, stable");
%! assert (M.Report.Termination.Determined, true);

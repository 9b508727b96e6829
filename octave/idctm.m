## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn  {} {@var{M} =} idctm (@var{B}, @var{F})
## @deftypefnx {} {@var{M} =} idctm (@var{B}, @var{F}, @var{name}, @var{value}, @dots{})
## @deftypefnx {} {@var{M} =} idctm (@var{s})
## The continuous-time model of CONTSID's older routines, kept as a thin
## alias: it returns an @code{idpoly} (Ts = 0)
## @example
## y = sum_j B_j(p) / F(p) u_j(t - nk_j Ts) (+ e)
## @end example
## @var{B}: numerator rows (a cell array of rows for several inputs);
## @var{F}: denominator, normalised to be monic (B with it).  With several
## inputs and one F the idpoly gets that F for every input (CONTSID's
## form, y = sum_j B_j/F u_j + e; theta and covariance count it once, the
## SITB parameter vector once per input); a cell of F's gives one
## denominator per input.
##
## Name-value pairs, or the fields of a struct @var{s}: @code{nk} (delays
## in samples), @code{Ts} (sampling interval of the estimation data:
## InputDelay = nk Ts), @code{InterSample}, @code{theta} and
## @code{covariance} (order [f b]; the covariance becomes the idpoly's,
## permuted to the SITB order), @code{noise_variance}, @code{method},
## @code{iterations}, @code{converged}, and @code{Report} (merged into the
## model's Report, e.g. Report.Fit).  These stay readable as
## @code{M.nk}, @code{M.theta}, @dots{} on the idpoly.
##
## @strong{Example}
## @example
## M = idctm (4, [1 2.4 4]);            # an idpoly, 4/(s^2 + 2.4 s + 4)
## y = simc (M, prbs (8, 4), 0.1);
## @end example
## @seealso{idpoly, srivc, lssvf, simc, comparec}
## @end deftypefn

function varargout = idctm (varargin)
  varargout = contsid_guard ("idctm", @idctm_body, nargout, varargin);
endfunction

function [M, varargout] = idctm_body (varargin)
  contsid_nargchk ("idctm", nargin, nargout, [0 Inf], 1);
  fields = {"B", "F", "nk", "Ts", "InterSample", "theta", "covariance", ...
            "noise_variance", "method", "iterations", "converged", "Report"};
  if (nargin == 1 && isa (varargin{1}, "idpoly"))
    M = varargin{1};
    return;
  endif
  if (nargin == 1 && isstruct (varargin{1}) && isscalar (varargin{1}))
    s = varargin{1};
  elseif (nargin >= 2 && mod (nargin, 2) == 0)
    s = struct ("B", {varargin(1)}, "F", {varargin(2)});
    s.B = varargin{1};
    s.F = varargin{2};
    for i = 3:2:nargin
      if (! ischar (varargin{i}) || ! any (strcmp (varargin{i}, fields)))
        error ("idctm:badOption", "idctm: argument %d is not a property name",
               i);
      endif
      s.(varargin{i}) = varargin{i+1};
    endfor
  else
    error ("idctm:badInput", "idctm: expected B and F, or a struct");
  endif
  if (! isfield (s, "B") || ! isfield (s, "F"))
    error ("idctm:badInput", "idctm: the model needs B and F");
  endif
  unknown = setdiff (fieldnames (s), fields);
  if (! isempty (unknown))
    error ("idctm:badOption", "idctm: unknown property '%s'", unknown{1});
  endif
  B = s.B;
  if (! iscell (B))
    B = {B};
  endif
  F = s.F;
  common = ! iscell (F);
  if (common)
    F = {F};
  endif
  for j = 1:numel (F)
    f = F{j};
    if (! isfloat (f) || issparse (f) || ! isreal (f) || ! isvector (f)
        || numel (f) < 2
        || f(1) == 0 || any (! isfinite (f)))
      error ("idctm:badInput", "idctm: F must be a finite [1 f1 .. f_nf]");
    endif
  endfor
  if (! common && numel (F) != numel (B))
    error ("idctm:badInput", "idctm: one F per input (%d), got %d",
           numel (B), numel (F));
  endif
  for j = 1:numel (B)
    g = F{min (j, numel (F))}(1);
    if (! isfloat (B{j}) || issparse (B{j}) || ! isreal (B{j}) || isempty (B{j})
        || ! isvector (B{j}) || any (! isfinite (B{j})))
      error ("idctm:badInput", "idctm: B must be finite real rows");
    endif
    B{j} = double (B{j}(:).') / g;
    if (numel (B{j}) > numel (F{min (j, numel (F))}))
      error ("idctm:badInput", "idctm: improper model (deg B > deg F)");
    endif
  endfor
  F = cellfun (@(f) double (f(:).') / f(1), F, "UniformOutput", false);
  try
    M = idpoly (1, B, 1, 1, F, 1, 0);
  catch err
    as_idctm (err, "B, F");
  end_try_catch
  rep = struct ();
  if (isfield (s, "Ts") && ! isempty (s.Ts))
    rep.DataUsed = struct ("Ts", s.Ts);
  endif
  if (isfield (s, "Report"))
    M = set (M, "Report", s.Report);
  endif
  if (! isempty (fieldnames (rep)))
    M = set (M, "Report", rep);
  endif
  for f = {"nk", "InterSample", "theta", "covariance", "noise_variance", ...
           "method", "iterations", "converged"}
    if (isfield (s, f{1}) && ! isempty (s.(f{1})))
      try
        M = set (M, f{1}, s.(f{1}));
      catch err
        as_idctm (err, f{1});
      end_try_catch
    endif
  endfor
endfunction

## The idpoly checks the values; the error is ours.
function as_idctm (err, what)
  reason = regexprep (err.identifier, '^.*:', "");
  if (isempty (regexp (reason, '^[A-Za-z]\w*$', "once")))
    reason = "badInput";
  endif
  error (["idctm:" reason], "idctm: %s: %s", what,
         regexprep (err.message, '^[^:]*: *', ""));
endfunction

%!test
%! M = idctm (4, [2 4.8 8]);
%! assert (class (M), "idpoly");
%! assert (M.F, [1 2.4 4]);
%! assert (M.B, 2);
%! assert (M.theta, [2.4 4 2]);
%! assert (M.nk, 0);
%! assert (M.Ts, 0);

%!test  # two inputs, common denominator, delays in samples
%! M = idctm ({1, [1 2]}, [1 3 2], "nk", [0 1], "Ts", 0.1);
%! assert (M.nk, [0 1]);
%! assert (M.InputDelay, [0; 0.1]);
%! assert (M.F, {[1 3 2], [1 3 2]});
%! assert (M.theta, [3 2 1 1 2]);
%! C = diag ([1 2 3 4 5]);
%! M = idctm (struct ("B", {{1, [1 2]}}, "F", [1 3 2], "covariance", C));
%! assert (M.covariance, C, 1e-12);
%! [~, sd] = getpvec (M);             # pvec [b1 b2 f(u1) f(u2)]
%! assert (sd.^2, [3 4 5 1 2 1 2]', 1e-12);

%!test  # the covariance, given in [f b] order, is SITB's in [b f] order
%! C = [4 1 0; 1 9 0; 0 0 16];
%! M = idctm (struct ("B", 5, "F", [1 2 3], "covariance", C,
%!                    "method", "srivc", "converged", true));
%! [p, sd] = getpvec (M);
%! assert (p, [5; 2; 3]);
%! assert (sd, [4; 2; 3]);
%! assert (M.covariance, C);
%! assert (M.method, "srivc");

%!error id=idctm:badInput idctm (1)
%!error id=idctm:badInput idctm (1, [0 1])
%!error id=idctm:badInput idctm ([1 2 3], [1 1])
%!error id=idctm:badInput idctm ({"a"}, [1 1])
%!error id=idctm:badOption idctm (1, [1 1], "bogus", 1)
%!error id=idctm:badOption idctm (struct ("B", 1, "F", [1 1], "bogus", 1))
%!error id=idctm:badInput idctm ({1, 2}, {[1 1]})
%!error id=idctm:badInput idctm (4, [1 2.4 4], "nk", NaN)
%!error id=idctm:badInput idctm (sparse (4), uint16 ([1 2 4]))
%!error id=idctm:badInput idctm (int8 (4), [1 2.4 4])
%!error id=idctm:badInput idctm (4, [1 2.4 4], "nk", -1)
%!error id=idctm:badInput idctm (struct ("B", 4, "F", [1 2.4 4], "nk", Inf))

%!demo
%! M = idctm (4, [1 2.4 4])
%! y = simc (M, ones (100, 1), 0.05); plot (y);

## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{data} =} merge (@var{d1}, @var{d2}, @dots{})
## A multi-experiment set with the experiments of @var{d1}, @var{d2},
## @dots{} in order.
##
## Each experiment keeps its own sampling interval or sampling instants, so
## records sampled differently can be kept together; @code{InterSample} is
## kept (the sets with inputs must agree on it: @code{iddata:notSupported}
## otherwise).  The sets must have the same numbers of outputs and inputs
## (@code{iddata:dimensionMismatch}).  Select an experiment back with
## @code{getexp (data, k)} or @code{data(:, :, :, k)}.
## @seealso{getexp, cat, vertcat}
## @end deftypefn

function varargout = merge (varargin)
  varargout = contsid_guard ({"merge", "iddata"}, @merge_body, nargout,
                             varargin);
endfunction

function [dat, varargout] = merge_body (varargin)
  contsid_nargchk ("merge", nargin, nargout, [0 Inf], 1);
  dat = concat_sets (3, varargin, "iddata: merge");
endfunction

%!test
%! t = cumsum (0.1 + mod ((1:30).', 3) / 100);
%! d1 = iddata (sin (t), cos (t), "SamplingInstants", t, "InterSample", "foh");
%! d2 = iddata ((1:20).', (1:20).', 0.2, "InterSample", "foh");
%! m = merge (d1, d2);
%! assert (size (m), [50, 1, 1, 2]);
%! assert (m.InterSample, "foh");
%! assert (m.Ts, {[]; 0.2});
%! assert (m.SamplingInstants, {t; (0:19).' * 0.2});
%! assert (struct (getexp (m, 1)), struct (d1));
%! assert (struct (getexp (m, 2)), struct (d2));
%! mm = merge (m, d2);
%! assert (mm.N, [30, 20, 20]);

## an FOH estimate on one experiment of a merge equals the one on its set
%!test
%! Ts = 0.05;
%! tt = (0:999).' * Ts;
%! uu = sin (0.9 * tt) + sign (sin (0.31 * tt));
%! yy = lsim (c2d (tf (2, [1, 3, 2]), Ts, "foh"), uu);
%! d1 = iddata (yy, uu, Ts, "InterSample", "foh");
%! d2 = iddata (yy(1:2:end), uu(1:2:end), 2 * Ts, "InterSample", "foh");
%! m = merge (d1, d2);
%! for k = 1:2
%!   a = srivc (getexp (m, k), [1 2 0]);
%!   b = srivc ({d1, d2}{k}, [1 2 0]);
%!   assert ([a.B, a.F], [b.B, b.F]);
%! endfor

%!error id=iddata:notSupported
%! merge (iddata (1, 1, 1, "InterSample", "foh"), iddata (1, 1, 1));
%!error id=iddata:dimensionMismatch
%! merge (iddata (1, 1, 1), iddata (1, [1 1], 1));
%!error id=iddata:badInput merge (iddata (1, 1, 1), 5)

%!demo
%! d1 = iddata (randn (100, 1), randn (100, 1), 0.1, "InterSample", "foh");
%! d2 = iddata (randn (80, 1), randn (80, 1), 0.05, "InterSample", "foh");
%! m = merge (d1, d2)

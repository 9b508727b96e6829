## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{data} =} horzcat (@var{d1}, @var{d2}, @dots{})
## @code{[d1, d2, @dots{}]}: the outputs of every set, then the inputs of
## every set, over the common samples.
##
## The sets must have the same numbers of experiments and samples and the
## same sampling (interval, instants or frequencies), and the sets with
## inputs the same @code{InterSample}; otherwise the error is identified
## (see @code{help iddata/cat}).  This is how frequency-domain data are
## assembled from a simulated output and its input:
## @code{datafreq = [Y, U]}.  With the operator form, Octave 7 reports a
## failure as @qcode{"iddata/horzcat method failed"} without identifier;
## the reason comes just before as a warning with the identifier.
## @seealso{cat, vertcat, merge}
## @end deftypefn

function varargout = horzcat (varargin)
  varargout = contsid_guard ({"horzcat", "iddata"}, @horzcat_body, nargout,
                             varargin);
endfunction

function [dat, varargout] = horzcat_body (varargin)
  contsid_nargchk ("horzcat", nargin, nargout, [0 Inf], 1);
  dat = concat_sets (2, varargin, "iddata: horzcat");
endfunction

%!shared y, u
%! y = sin ((1:50).');
%! u = cos ((1:50).');

%!test
%! d = [iddata(y, [], 0.1), iddata([], u, 0.1, "InterSample", "foh")];
%! assert (size (d), [50, 1, 1, 1]);
%! assert (d.y, y);
%! assert (d.u, u);
%! assert (d.InterSample, "foh");
%! d = [iddata(y, u, 0.1, "OutputName", "a"), iddata(2*y, -u, 0.1)];
%! assert (d.y, [y, 2*y]);
%! assert (d.u, [u, -u]);
%! assert (d.OutputName, {"a"; ""});
%! t = cumsum (0.1 + (1:50).'/1000);
%! d = [iddata(y, [], "SamplingInstants", t), ...
%!      iddata([], u, "SamplingInstants", t)];
%! assert (d.SamplingInstants, t);

## an FOH estimate on [output set, FOH input set] is the one on the FOH set
%!test
%! Ts = 0.05;
%! tt = (0:999).' * Ts;
%! uu = sin (0.9 * tt) + sign (sin (0.31 * tt));
%! yy = lsim (c2d (tf (2, [1, 3, 2]), Ts, "foh"), uu);
%! joined = [iddata(yy, [], Ts), iddata([], uu, Ts, "InterSample", "foh")];
%! assert (joined.InterSample, "foh");
%! a = srivc (joined, [1 2 0]);
%! b = srivc (iddata (yy, uu, Ts, "InterSample", "foh"), [1 2 0]);
%! assert ([a.B, a.F], [b.B, b.F]);

%!error id=iddata:dimensionMismatch
%! horzcat (iddata (y, u, 0.1), iddata (y(1:10), u(1:10), 0.1));
%!error id=iddata:badInput horzcat (iddata (y, u, 0.1), iddata (y, u, 0.2))
%!error id=iddata:badInput
%! horzcat (iddata (y, u, 0.1), iddata (y, u, "SamplingInstants", (1:50) / 10));
%!error id=iddata:notSupported
%! horzcat (iddata (y, u, 0.1), iddata (y, u, 0.1, "InterSample", "foh"));
%!error id=iddata:dimensionMismatch
%! horzcat (iddata (y, u, 0.1), iddata ({y, y}, {u, u}, 0.1));
%!error <iddata/horzcat method failed> [iddata(y, u, 0.1), iddata(y, u, 0.2)]

%!demo
%! ## frequency-domain data from an output and an input set
%! u = iddata ([], randn (256, 1), 0.1, "InterSample", "bl");
%! U = fft (u);
%! Y = iddata (U.u ./ (1 + 1i * U.Frequency), [], U.Ts, "Frequency",
%!             U.Frequency);
%! datafreq = [Y, U]

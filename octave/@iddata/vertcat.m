## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{data} =} vertcat (@var{d1}, @var{d2}, @dots{})
## @code{[d1; d2; @dots{}]}: the samples of @var{d2} after those of
## @var{d1}, in every experiment.
##
## @code{InterSample} is kept (sets with inputs must agree on it, or the
## error is @code{iddata:notSupported}).  Regularly sampled sets must have
## the same @code{Ts}; with sampling instants, each set's instants must
## follow those of the sets before, and the result has the joined instants
## (a regular set counts from time 0).  Anything else is an identified
## error (see @code{help iddata/cat}).
##
## Octave 7 replaces the message of an error raised in a class's
## concatenation method called by the operator (@code{[d1; d2]}) with
## @qcode{"iddata/vertcat method failed"} and drops its identifier; the
## reason is therefore also issued as a warning (with the identifier)
## just before the error.
## @seealso{cat, horzcat, merge}
## @end deftypefn

function varargout = vertcat (varargin)
  varargout = contsid_guard ({"vertcat", "iddata"}, @vertcat_body, nargout,
                             varargin);
endfunction

function [dat, varargout] = vertcat_body (varargin)
  contsid_nargchk ("vertcat", nargin, nargout, [0 Inf], 1);
  dat = concat_sets (1, varargin, "iddata: vertcat");
endfunction

%!shared t, y, u
%! t = (0:199).' * 0.05;
%! u = sign (sin (1.3 * t));
%! y = sin (t);

%!test
%! d1 = iddata (y(1:120), u(1:120), 0.05, "InterSample", "foh");
%! d2 = iddata (y(121:end), u(121:end), 0.05, "InterSample", "foh");
%! d = [d1; d2];
%! assert (d.InterSample, "foh");
%! assert (d.Ts, 0.05);
%! assert (d.y, y);
%! assert (d.u, u);
%! assert (struct (d), struct (iddata (y, u, 0.05, "InterSample", "foh")));
%! e = [[]; d1; []; d2];
%! assert (struct (e), struct (d));

## irregular records keep their instants; regular + irregular too
%!test
%! ti = t + 0.01 * sin (t);
%! d1 = iddata (y(1:120), u(1:120), "SamplingInstants", ti(1:120));
%! d2 = iddata (y(121:end), u(121:end), "SamplingInstants", ti(121:end));
%! d = [d1; d2];
%! assert (d.SamplingInstants, ti);
%! assert (d.Ts, []);
%! d0 = iddata (y(1:120), u(1:120), 0.05);
%! d = [d0; d2];
%! assert (d.SamplingInstants, [t(1:120); ti(121:end)], 1e-15);

## output-only and input-only sets; time series of two experiments
%!test
%! d = [iddata(y(1:10), [], 0.05); iddata(y(11:20), [], 0.05)];
%! assert (size (d), [20, 1, 0, 1]);
%! d = [iddata([], u(1:10), 0.05); iddata([], u(11:20), 0.05)];
%! assert (size (d), [20, 0, 1, 1]);
%! m = iddata ({y, y(1:50)}, {u, u(1:50)}, {0.05, 0.1});
%! d = [m; m];
%! assert (d.N, [400, 100]);
%! assert (d.Ts, {0.05; 0.1});

## the FOH rule survives: an FOH estimate on [d1; d2] is the estimate on
## the same signals built as one FOH record (the control package's
## vertcat turned them into ZOH)
%!test
%! Ts = 0.05;
%! tt = (0:1999).' * Ts;
%! uu = sin (0.7 * tt) + sign (sin (0.23 * tt));
%! yy = lsim (c2d (tf (2, [1, 3, 2]), Ts, "foh"), uu);
%! d1 = iddata (yy(1:1200), uu(1:1200), Ts, "InterSample", "foh");
%! d2 = iddata (yy(1201:end), uu(1201:end), Ts, "InterSample", "foh");
%! whole = iddata (yy, uu, Ts, "InterSample", "foh");
%! joined = [d1; d2];
%! assert (joined.InterSample, "foh");
%! m1 = srivc (joined, [1 2 0]);
%! m2 = srivc (whole, [1 2 0]);
%! assert ([m1.B, m1.F], [m2.B, m2.F]);
%! ## noise-free: FOH within the start-up transient's bias (0.07 %), the
%! ## same signals read as ZOH 5 % off
%! assert ([m1.B, m1.F], [2, 1, 3, 2], -2e-3);
%! mz = srivc (iddata (yy, uu, Ts, "InterSample", "zoh"), [1 2 0]);
%! assert (max (abs ([mz.B, mz.F] - [2, 1, 3, 2]) ./ [2, 1, 3, 2]) > 0.05);

%!error id=iddata:badInput vertcat (iddata (y, u, 0.05), iddata (y, u, 0.1))
%!error id=iddata:badInput
%! vertcat (iddata (y, u, "SamplingInstants", t),
%!          iddata (y, u, "SamplingInstants", t));
%!error id=iddata:badInput
%! vertcat (iddata (y, u, "SamplingInstants", t), iddata (y, u, 0.05));
%!error id=iddata:badInput
%! vertcat (iddata (y, u, -1), iddata (y, u, "SamplingInstants", t + 20));
%!error id=iddata:notSupported
%! vertcat (iddata (y, u, 0.05, "InterSample", "foh"), iddata (y, u, 0.05));
%!error id=iddata:dimensionMismatch
%! vertcat (iddata (y, u, 0.05), iddata (y, [u u], 0.05));
%!error id=iddata:dimensionMismatch
%! vertcat (iddata (y, u, 0.05), iddata ([y y], u, 0.05));
%!error id=iddata:dimensionMismatch
%! vertcat (iddata (y, u, 0.05), iddata ({y, y}, {u, u}, 0.05));
%!error id=iddata:badInput
%! vertcat (iddata (y, u, 0.05), fft (iddata (y, u, 0.05)));
%!error id=iddata:badInput vertcat (iddata (y, u, 0.05), [y u])
## the operator form fails too; Octave 7 replaces the message and drops the
## identifier of an error raised in a class's concatenation method
%!error <iddata/vertcat method failed> [iddata(y, u, 0.05); iddata(y, u, 0.1)]
## ... so the reason comes first as a warning with the error's identifier
%!test
%! lastwarn ("");
%! try
%!   evalc ("[iddata(y, u, 0.05); iddata(y, u, 0.1)]");
%! end_try_catch
%! [msg, id] = lastwarn ();
%! assert (id, "iddata:badInput");
%! assert (! isempty (strfind (msg, "sampled every 0.1")));

%!demo
%! ## two irregularly sampled records of one run, kept irregular
%! t = cumsum (0.1 + 0.05 * rand (200, 1));
%! d1 = iddata (sin (t(1:100)), cos (t(1:100)), "SamplingInstants", t(1:100));
%! d2 = iddata (sin (t(101:end)), cos (t(101:end)),
%!              "SamplingInstants", t(101:end));
%! d = [d1; d2];
%! isequal (d.SamplingInstants, t)

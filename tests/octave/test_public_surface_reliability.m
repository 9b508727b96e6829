## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {} test_public_surface_reliability ()
## Calls across the public surface that once hung, failed without an
## identifier (or under another function's) or returned garbage
## silently, each checked for its identified error, its warning or its
## correct result.  The classes of problem and where they are handled:
## @itemize
## @item non-finite parameters (the control package's pole and
## realisation routines never return on them): the model classes'
## @code{setpvec} and @code{set} (@code{pvec_set}, @code{set_prop});
## @item errors of inner calls: every public function re-raises them under
## its own identifier (@code{contsid_guard}, @code{contsid_rethrow});
## @item integer-typed or out-of-range arguments: the argument readers;
## @item a cut-off above the Nyquist frequency (a warning), an input zero
## at every sample (an error), non-finite tracks (an error): the readers
## and the back end of the recursive estimators;
## @item missing samples in the data methods (@code{detrend} bridges them,
## @code{fft} refuses them, as @code{resample}), a constant output in
## @code{comparec} (NaN and a warning).
## @end itemize
## The record is a PRBS into 4/(s^2+2.4s+4), 381 samples, Ts = 0.05.
## @end deftypefn

function test_public_surface_reliability ()
  root = ctid_test_root ();
  addpath (fullfile (root, "octave"));
  Ts = 0.05;
  k = (1:381)';
  u = sign (sin (k * 0.61 + 0.2) + 0.5 * sin (k * 0.23));
  u(u == 0) = 1;
  Mp = idpoly (1, 4, 1, 1, [1 2.4 4], "Ts", 0);
  y = simc (Mp, u, Ts);
  d = iddata (y, u, Ts, "InterSample", "zoh");
  dz = iddata (y, zeros (381, 1), Ts, "InterSample", "zoh");
  nfail = 0;

  ## Non-finite parameters: refused before they reach a routine that
  ## does not return.
  nfail += err ("idpoly:badInput", @() setpvec (Mp, [4; 2.4; NaN]));
  nfail += err ("idpoly:badInput", @() set (Mp, "theta", [4 2.4 NaN]));
  nfail += err ("idtf:badInput", @() setpvec (idtf (2, [1 3 2]),
                                              [Inf 3 2 0]));
  nfail += err ("idss:badInput", @() setpvec (idss (-1, 1, 1, 0),
                                              [NaN 1 1 0]));
  P = idproc ("P1D", "Kp", 2, "Tp1", 0.5, "Td", 0.1);
  nfail += err ("idproc:badInput", @() set (P, "Kp", Inf));
  nfail += err ("idpoly:badInput", @() set (Mp, "covariance", -eye (3)));
  nfail += check (isequal (getcov (setcov (Mp, int8 (eye (3)))), eye (3)),
                  "setcov takes an integer-typed covariance");

  ## Argument readers.
  nfail += err ("idmodel:badInput", @() idmodel ("idtf", struct (), 1, NaN));
  nfail += err ("idmodel:badInput", @() idmodel ("idtf", struct (), -1, 1));
  nfail += err ("step:badInput", @() step (4, [1 2.4 4], {1}));
  nfail += err ("bode:badInput", @() bode (4, [1 2.4 4], {1}));
  nfail += err ("pzmap:badInput", @() pzmap (4, [1 2.4 4], {1}));
  nfail += err ("svfcutoff:badInput",
                @() svfcutoff (d, [1 2 0], "segments", 1e308));
  nfail += check (isequal (get (nkshift (d, int8 (2)), "OutputData"),
                           y(3:end)),
                  "nkshift takes an integer-typed shift");

  ## An inner failure carries the identifier of the function called (a
  ## numerator-only model once stopped residtrace on Octave's own
  ## index-out-of-bounds)
  try
    residtrace (d, idpoly ([1 2.4 4], [], "Ts", 0));
  catch e
    nfail += check (strncmp (e.identifier, "residtrace:", 11),
                    sprintf ("residtrace's identifier, got '%s'",
                             e.identifier));
  end_try_catch

  ## Recursive estimators: excitation, cut-off, finite results.
  for f = {"rlssvf", "rivsvf", "rarxc"}
    nfail += err ([f{1} ":badInput"],
                  @() feval (f{1}, dz, [2 1 1], "lambda_svf", 3));
  endfor
  nfail += err ("rsrivc:badInput", @() rsrivc (dz, [1 2 0], "lambda_svf", 3));
  nfail += warn ("rlssvf:cutoffAboveNyquist",
                 @() rlssvf (d, [2 1 0], "lambda_svf", 1e9));
  nfail += warn ("rsrivc:cutoffAboveNyquist",
                 @() rsrivc (d, [1 2 0], "lambda_svf", 1e9, "tsiv", 5));
  warning ("off", "rivsvf:cutoffAboveNyquist", "local");
  nfail += err ("rivsvf:numericalFailure",
                @() two_outputs (@rivsvf, d, [2 1 0], "lambda_svf", 1e9,
                                 "tsiv", 5));

  ## Data methods and missing samples.
  yg = y;
  yg(100:110) = NaN;
  dg = iddata (yg, u, Ts);
  dd = detrend (dg);
  have = ! isnan (yg);
  nfail += check (isequal (isnan (get (dd, "OutputData")), ! have)
                  && abs (mean (get (dd, "OutputData")(have))) < 1e-12,
                  "detrend keeps missing samples missing, removes the mean");
  nfail += err ("iddata:notSupported", @() fft (dg));

  ## A constant output: Fit and RT2 undefined, with a warning.
  dc = iddata (2 * ones (381, 1), u, Ts);
  nfail += warn ("comparec:constantOutput",
                 @() two_outputs (@comparec, dc, Mp));
  warning ("off", "comparec:constantOutput", "local");
  [~, info] = comparec (dc, Mp);
  nfail += check (isnan (info.Fit) && isnan (info.RT2),
                  "comparec: Fit and RT2 of a constant output are NaN");

  ## The private helpers behind these checks.
  for f = {"contsid_guard.m", "contsid_rethrow.m", "contsid_check_input.m", ...
           "contsid_check_cutoff.m", "contsid_check_track.m"}
    ctid_run_private_tests (f{1});
  endfor

  if (nfail > 0)
    error ("test_public_surface_reliability: %d failures", nfail);
  endif
  printf ("test_public_surface_reliability: all checks passed\n");
endfunction

function n = err (id, f)
  n = 0;
  try
    f ();
    printf ("  FAIL %s: no error from %s\n", id, func2str (f));
    n = 1;
  catch e
    if (! strcmp (e.identifier, id))
      printf ("  FAIL %s: got '%s': %s\n", id, e.identifier, e.message);
      n = 1;
    endif
  end_try_catch
endfunction

function n = warn (id, f)
  n = 0;
  lastwarn ("");
  f ();
  [~, got] = lastwarn ();
  if (! strcmp (got, id))
    printf ("  FAIL %s: no such warning from %s (last: '%s')\n", id,
            func2str (f), got);
    n = 1;
  endif
endfunction

## (nthargout would drop the error's identifier)
function two_outputs (f, varargin)
  [~, ~] = f (varargin{:});
endfunction

function n = check (ok, what)
  n = ! ok;
  if (n)
    printf ("  FAIL %s\n", what);
  endif
endfunction

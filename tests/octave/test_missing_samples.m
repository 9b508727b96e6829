## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {} test_missing_samples ()
## Missing samples across every front-end that reads a time
## record: one record with a gap of missing samples (NaN in y, and a
## shorter one in u), one table of calls.  Each front-end is declared
## either
## @itemize
## @item @qcode{"bridge"}: it reads the record through the common
## mechanism (@code{contsid_recursive_args}: the present samples on their
## own instants, the continuous-time filters propagate over the gap).  Its
## result must be finite and equal, to rounding, the result of the same
## call on the irregular record of the present samples (the identity that
## defines the mechanism); it must say which samples were missing
## (@code{info.missing}, the N-by-1 mask) where it returns an @var{info};
## and with @code{"Missing", "error"} it must refuse the gap
## (@code{<name>:badInput});
## @item @qcode{"refuse"}: it does not support gaps and says so, with an
## identified error @code{<name>:badInput} or @code{<name>:notSupported}
## whose message names the NaN or the missing samples.
## @end itemize
## Never a NaN estimate, a silently different answer or an error without
## identifier.  A front-end that learns to bridge moves from one list to
## the other.
## @end deftypefn

function test_missing_samples ()
  root = ctid_test_root ();
  addpath (fullfile (root, "octave"));
  pkg load control
  warning ("off", "all");
  graphics_toolkit ("gnuplot");
  set (0, "defaultfigurevisible", "off");
  randn ("state", 12);
  rand ("state", 12);
  Ts = 0.05;
  N = 1200;
  t = (0:N-1)' * Ts;
  u = kron (sign (randn (N / 20, 1)), ones (20, 1));
  y = lsim (tf (2, [1 1.5 2]), u, t) + 0.01 * randn (N, 1);
  missing = false (N, 1);
  missing(400:430) = true;          # a gap in y
  missing(800:805) = true;          # and one in u
  yg = y; yg(400:430) = NaN;
  ug = u; ug(800:805) = NaN;
  gap = iddata (yg, ug, Ts);
  ## the same present samples as an irregular record
  irr = iddata (y(! missing), u(! missing), "SamplingInstants",
                t(! missing));
  cl = iddata (u, u, Ts);           # a stand-in closed-loop record
  C = struct ("num", [1 -0.5], "den", [1 -1]);
  M0 = idtf (2, [1 1.5 2]);
  w = logspace (-1, 1, 10)';
  ## the external signals of the closed-loop calls, sampled as the record
  ## (its present samples on the irregular record)
  rs = @(d) u(rows (get (d, "OutputData")) == N | ! missing);
  ## The recursive closed-loop estimators' loop u = r1 + Cp (r2 - y), with
  ## r2 = 0 and a proportional Cp (a stable loop), holds on the record with
  ## r1 = u + Cp y: their instruments then come from a loop that the data
  ## obey (with r1 = u and C the recursion diverged and its frozen-model
  ## output overflowed).
  Cp = struct ("num", 0.2, "den", 1);
  r1 = u + 0.2 * y;
  r1s = @(d) r1(rows (get (d, "OutputData")) == N | ! missing);
  rec = @(d) {"controller", Cp, "r1", r1s(d), "r2", 0 * r1s(d)};

  ## Bridged: {name, call (data, extra options), number of outputs, index
  ## of the estimate among them, index of the info output with the field
  ## missing (0: none)}.  The recursive estimators run with GapSettle 0
  ## (no hold after a gap), so that the identity with the irregular record,
  ## which has no gap to settle from, is exact.
  g0 = {"GapSettle", 0};
  bridged = {
    "lssvf",       @(d, varargin) lssvf (d, [2 1 0], 3, varargin{:}), 1, 1, 0
    "ivsvf",       @(d, varargin) ivsvf (d, [2 1 0], 3, varargin{:}), 1, 1, 0
    "srivc",       @(d, varargin) srivc (d, [1 2 0], varargin{:}), 6, 1, 6
    "clsrivc",     @(d, varargin) clsrivc (d, rs(d), [1 2 0], C,
                                           varargin{:}), 4, 1, 4
    "svfscaling",  @(d, varargin) svfscaling (d, [2 1 0], 3,
                                              varargin{:}), 1, 1, 0
    "svfcutoff",   @(d, varargin) svfcutoff (d, [1 2 0], varargin{:}), 1, 1, 0
    "rlssvf",      @(d, varargin) rlssvf (d, [2 1 0], 3, g0{:},
                                          varargin{:}), 4, 1, 4
    "rivsvf",      @(d, varargin) rivsvf (d, [2 1 0], 3, g0{:},
                                          varargin{:}), 4, 1, 4
    "rsrivc",      @(d, varargin) rsrivc (d, [1 2 0], 3, g0{:},
                                          varargin{:}), 4, 1, 4
    "rlsconverge", @(d, varargin) rlsconverge (d, [2 1 0], "lambda_svf", 3,
                                               varargin{:}), 3, 3, 0
    "qnml",        @(d, varargin) qnml (d, [2 1 0], "lambda_svf", 3, g0{:},
                                        varargin{:}), 1, 1, 0
    "clrivsvf",    @(d, varargin) clrivsvf (d, [2 1 0], 3, rec(d){:}, g0{:},
                                            varargin{:}), 4, 1, 4
    "clrsrivc",    @(d, varargin) clrsrivc (d, [1 2 0], 3, rec(d){:}, g0{:},
                                            varargin{:}), 4, 1, 4
  };
  ## Refused: {name, call (data)}.
  refused = {
    "rivc",         @(d) rivc (d, [1 1 1 2 0])
    "tfrivc",       @(d) tfrivc (d, 2, 0)
    "clrivc",       @(d) clrivc (d, cl, [1 1 1 2 0], C)
    "cl2srivc",     @(d) cl2srivc (d, cl, [1 2 0], [2 2 0])
    "tfsrivc",      @(d) tfsrivc (d, 2, 0)
    "tfsrivc_init", @(d) tfsrivc_init (d, 2, 0)
    "tfcoe",        @(d) tfcoe (d, 2, 0)
    "procsrivc",    @(d) procsrivc (d, "P2")
    "hsrivc",       @(d) hsrivc (d, [1 2 0])
    "hrivc",        @(d) hrivc (d, [1 1 1 2 0])
    "hwsrivc",      @(d) hwsrivc (d, [1 3 0])
    "oe",           @(d) oe (d, [1 2 0])
    "tfest",        @(d) tfest (d, 2, 0)
    "arx",          @(d) arx (d, [2 1 1])
    "rarx",         @(d) rarx (d, [2 1 1], "ff", 0.99)
    "rarxc",        @(d) rarxc (d, [2 1 0], "lambda_svf", 3)
    "srivcstruc",   @(d) srivcstruc (d, d, [1 2 0; 2 2 0])
    "comparec",     @(d) comparec (d, M0)
    "residc",       @(d) residc (d, M0)
    "simc",         @(d) simc (M0, d)
    "cra",          @(d) cra (d)
    "delayest",     @(d) delayest (d)
    "spafdr",       @(d) spafdr (d, 20, w)
    "idresamp",     @(d) idresamp (d, 2)
  };
  nfail = 0;
  for i = 1:rows (refused)
    [name, f] = refused{i, :};
    [~, err] = run (f, gap, 1);
    if (isempty (err))
      nfail += fail (name, "accepted a record with missing samples");
    elseif (isempty (regexp (err.identifier,
                             ['^' name ':(badInput|notSupported)$'])))
      nfail += fail (name, sprintf ("error id '%s': %s", err.identifier,
                                    err.message));
    elseif (isempty (regexpi (err.message, "NaN|missing")))
      nfail += fail (name, ["the refusal does not name the missing ", ...
                            "samples: " err.message]);
    endif
  endfor
  for i = 1:rows (bridged)
    [name, f, nout, iest, iinfo] = bridged{i, :};
    [out, err] = run (f, gap, nout);
    if (! isempty (err))
      nfail += fail (name, sprintf ("refused the gap (%s): %s",
                                    err.identifier, err.message));
      continue;
    endif
    if (! all_finite (out{iest}))
      nfail += fail (name, "non-finite estimate on a record with a gap");
    endif
    [ref, err] = run (f, irr, nout);
    if (! isempty (err))
      nfail += fail (name, ["the irregular record of the present ", ...
                            "samples failed: " err.message]);
    elseif (! same_estimate (out{iest}, ref{iest}, missing))
      nfail += fail (name, ["the estimate differs from the one on the ", ...
                            "irregular record of the present samples"]);
    endif
    if (iinfo > 0 && ! (isstruct (out{iinfo})
                        && isfield (out{iinfo}, "missing")
                        && isequal (out{iinfo}.missing(:), missing)))
      nfail += fail (name, "info.missing does not give the missing samples");
    endif
    [~, err] = run (f, gap, 1, "Missing", "error");
    if (isempty (err)
        || isempty (regexp (err.identifier, ['^' name ':badInput$'])))
      nfail += fail (name, "'Missing', 'error' did not refuse the gap");
    endif
  endfor
  ## residtrace bridges the gap as the estimators do and leaves the
  ## missing samples out of its figures (R.missing).
  [out, err] = run (@(d) residtrace (d, M0), gap, 1);
  if (! isempty (err))
    nfail += fail ("residtrace", sprintf ("refused the gap (%s): %s",
                                          err.identifier, err.message));
  elseif (! (isfield (out{1}, "missing")
             && nnz (out{1}.missing.estimation)
                + nnz (out{1}.missing.validation) == nnz (missing)
             && isfinite (out{1}.rmse_final)))
    nfail += fail ("residtrace", ["R.missing does not give the missing ", ...
                                  "samples, or the final error is not finite"]);
  endif
  if (nfail > 0)
    error ("test_missing_samples: %d failures", nfail);
  endif
  printf (["test_missing_samples: %d front-ends bridge the gap, %d ", ...
           "refuse it\n"], rows (bridged), rows (refused));
endfunction

function [out, err] = run (f, d, nout, varargin)
  out = cell (1, nout);
  err = [];
  try
    [out{:}] = f (d, varargin{:});
  catch e
    err = e;
  end_try_catch
  close all;
endfunction

function n = fail (name, what)
  printf ("  FAIL %s: %s\n", name, what);
  n = 1;
endfunction

function x = numbers (m)
  if (isobject (m))
    try
      x = getpvec (m);
    catch
      x = m.theta;
    end_try_catch
  elseif (isstruct (m))
    c = struct2cell (m(:));
    c = c(cellfun (@(v) isnumeric (v) && ! isempty (v), c));
    x = cell2mat (cellfun (@(v) double (v(:)), c(:), "UniformOutput", false));
  else
    x = double (m);
  endif
endfunction

function tf = all_finite (m)
  x = numbers (m);
  tf = ! isempty (x) && all (isfinite (x(:)));
endfunction

## Equal to rounding; a per-sample estimate (N rows on the record with the
## gap, one row per present sample on the irregular one) is compared at
## the present samples.
function tf = same_estimate (a, b, missing)
  if (isnumeric (a) && rows (a) == numel (missing)
      && rows (b) == nnz (! missing))
    a = a(! missing, :);
  endif
  x = numbers (a);
  z = numbers (b);
  tf = (isequal (size (x), size (z))
        && all (abs (x(:) - z(:)) <= 1e-9 * max (1, abs (z(:)))));
endfunction

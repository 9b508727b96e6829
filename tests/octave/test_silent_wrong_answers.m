## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {} test_silent_wrong_answers ()
## Calls that could give a silently wrong answer, each checked in one place:
## the call must either give the right answer or raise an identified error
## @code{<function>:<reason>}.
## @itemize
## @item a second input column with a one-input order vector
## (@code{rlssvf}, @code{rivsvf}, @code{svfscaling}, @code{rlsconverge},
## iddata and numeric forms): an error, never the one-input result;
## @item concatenating or merging @qcode{"foh"} records keeps
## @qcode{"foh"}, and the FOH estimate of the concatenation equals the one
## of the whole record;
## @item concatenating irregular records keeps their instants;
## concatenating records of different Ts keeps each sample's instant;
## @item @code{lssvf}, @code{ivsvf}, @code{svfscaling}, @code{svfcutoff}
## on a constant output, @code{lssvf} on a 3-sample record: errors;
## @item @code{idctm (..., "nk", NaN)} (and Inf): an error;
## @item the same cases on the newer estimators (the refined-IV,
## Hammerstein, output-error and ARX families): a second input, a constant
## output, a 3-sample record, a NaN delay: each an identified error (a
## second input may also give a two-input model).
## @end itemize
## @end deftypefn

function test_silent_wrong_answers ()
  root = ctid_test_root ();
  addpath (fullfile (root, "octave"));
  warning ("off", "all");
  randn ("state", 3);
  rand ("state", 3);
  Ts = 0.05;
  N = 2000;
  u = sign (randn (N / 20, 1));
  u = kron (u, ones (20, 1));
  u2 = randn (N, 1);
  y = simc ([2.4 4 4], [2 1 0], u, Ts) + 0.01 * randn (N, 1);
  nfail = 0;

  ## A second input with a one-input order vector.
  two = iddata (y, [u u2], Ts);
  calls = {
    "rlssvf",      @() rlssvf (two, [2 1 0], 3)
    "rlssvf",      @() rlssvf (y, [u u2], Ts, [2 1 0], 3)
    "rivsvf",      @() rivsvf (two, [2 1 0], 3)
    "rivsvf",      @() rivsvf (y, [u u2], Ts, [2 1 0], 3)
    "svfscaling",  @() svfscaling (two, [2 1 0], "lambda_svf", 3)
    "rlsconverge", @() rlsconverge (two, [2 1 0], "lambda_svf", 3)
  };
  for i = 1:rows (calls)
    nfail += expect_error (calls{i, 1}, calls{i, 2},
                           sprintf ("second input ignored? (call %d)", i));
  endfor

  ## FOH records: concatenation and merge keep the rule, and the FOH
  ## estimate of the concatenation is the one of the whole record.
  d = iddata (y, u, Ts, "InterSample", "foh");
  d1 = iddata (y(1:1000), u(1:1000), Ts, "InterSample", "foh");
  d2 = iddata (y(1001:end), u(1001:end), Ts, "InterSample", "foh");
  c = [d1; d2];
  nfail += check (strcmp (c.InterSample, "foh"), "vertcat of foh is foh");
  m = merge (d1, d2);
  nfail += check (all (strcmp (m.InterSample, "foh")), "merge of foh is foh");
  th_whole = rlssvf (d, [2 1 0], 3);
  th_cat = rlssvf (c, [2 1 0], 3);
  nfail += check (isequal (th_whole, th_cat),
                  "FOH estimate of the concatenation = of the whole record");

  ## Irregular records and records of different Ts.
  t = cumsum (0.04 + 0.02 * rand (N, 1));
  i1 = iddata (y(1:1000), u(1:1000), "SamplingInstants", t(1:1000));
  i2 = iddata (y(1001:end), u(1001:end), "SamplingInstants", t(1001:end));
  ic = [i1; i2];
  nfail += check (isequal (ic.SamplingInstants, t),
                  "vertcat of irregular records keeps the instants");
  r1 = iddata (y(1:1000), u(1:1000), 0.05);
  r2 = iddata (y(1001:end), u(1001:end), 0.1);
  ## (vertcat called by name: Octave 7 drops the identifier of an error
  ## raised by a class's concatenation method called by the operator, see
  ## help iddata/vertcat)
  try
    rc = vertcat (r1, r2);
    ti = rc.SamplingInstants;
    want = [(0:999)' * 0.05; 1000 * 0.05 + (0:999)' * 0.1];
    nfail += check (isempty (rc.Ts) && max (abs (ti - want)) < 1e-9,
                    "vertcat of Ts 0.05 and 0.1 keeps each instant");
  catch err
    nfail += check (! isempty (regexp (err.identifier, '^iddata:\w+$')),
                    ["vertcat of different Ts: unidentified error: " ...
                     err.message]);
  end_try_catch

  ## Constant output, 3-sample record.
  k = iddata (ones (N, 1), u, Ts);
  calls = {
    "lssvf",      @() lssvf (k, [2 1 0], 3)
    "ivsvf",      @() ivsvf (k, [2 1 0], 3)
    "svfscaling", @() svfscaling (k, [2 1 0], "lambda_svf", 3)
    "svfcutoff",  @() svfcutoff (k, [1 2 0])
    "lssvf",      @() lssvf (iddata (y(1:3), u(1:3), Ts), [2 1 0], 3)
    "idctm",      @() idctm (4, [1 2.4 4], "nk", NaN)
    "idctm",      @() idctm (4, [1 2.4 4], "nk", Inf)
  };
  for i = 1:rows (calls)
    nfail += expect_error (calls{i, 1}, calls{i, 2},
                           sprintf ("degenerate call %d accepted", i));
  endfor

  ## The same cases on the newer estimators: a second input to a one-input
  ## estimator, a constant output, a 3-sample record, a NaN delay.  Each
  ## must be an identified error (a two-input record may also be accepted
  ## by an estimator whose model then has two inputs).
  one = iddata (y, u, Ts);
  cl = iddata (u, u, Ts);
  C = struct ("num", [1 -0.5], "den", [1 -1]);
  three = iddata (y(1:3), u(1:3), Ts);
  ## {name, call (data), call with a NaN delay ([] if it takes none)}
  newer = {
    "tfsrivc",      @(d) tfsrivc (d, 2, 0),   @() tfsrivc (one, 2, 0, NaN)
    "tfsrivc_init", @(d) tfsrivc_init (d, 2, 0), []
    "tfcoe",        @(d) tfcoe (d, 2, 0),     @() tfcoe (one, 2, 0, NaN)
    "tfrivc",       @(d) tfrivc (d, 2, 0),    @() tfrivc (one, 2, 0, NaN)
    "procsrivc",    @(d) procsrivc (d, "P2"), []
    "oe",           @(d) oe (d, [1 2 0]),     @() oe (one, [1 2 NaN])
    "tfest",        @(d) tfest (d, 2, 0),     @() tfest (one, 2, 0, NaN)
    "arx",          @(d) arx (d, [2 1 1]),    @() arx (one, [2 1 NaN])
    "rivc",         @(d) rivc (d, [1 1 1 2 0]), ...
                    @() rivc (one, [1 1 1 2 NaN])
    "clrivc",       @(d) clrivc (d, cl, [1 1 1 2 0], C), ...
                    @() clrivc (one, cl, [1 1 1 2 NaN], C)
    "cl2srivc",     @(d) cl2srivc (d, cl, [1 2 0], [2 2 0]), ...
                    @() cl2srivc (one, cl, [1 2 NaN], [2 2 0])
    "hsrivc",       @(d) hsrivc (d, [1 2 0]), @() hsrivc (one, [1 2 NaN])
    "hrivc",        @(d) hrivc (d, [1 1 1 2 0]), ...
                    @() hrivc (one, [1 1 1 2 NaN])
    "hwsrivc",      @(d) hwsrivc (d, [1 3 0]), @() hwsrivc (one, [1 3 NaN])
    "srivc",        @(d) srivc (d, [1 2 0]),  @() srivc (one, [1 2 NaN])
    "rarx",         @(d) rarx (d, [2 1 1], "ff", 0.99), ...
                    @() rarx (one, [2 1 NaN], "ff", 0.99)
    "rarxc",        @(d) rarxc (d, [2 1 1], "lambda_svf", 3), ...
                    @() rarxc (one, [2 1 NaN], "lambda_svf", 3)
    "delayest",     @(d) delayest (d),        []
  };
  for i = 1:rows (newer)
    [name, f, fnk] = newer{i, :};
    nfail += two_inputs (name, f, two);
    nfail += expect_error (name, @() f (k), [name ": constant output"]);
    nfail += expect_error (name, @() f (three), [name ": 3 samples"]);
    if (! isempty (fnk))
      nfail += expect_error (name, fnk, [name ": NaN delay"]);
    endif
  endfor
  if (nfail > 0)
    error ("test_silent_wrong_answers: %d failures", nfail);
  endif
  printf ("test_silent_wrong_answers: every case right or identified\n");
endfunction

function n = check (ok, what)
  n = 0;
  if (! ok)
    printf ("  FAIL %s\n", what);
    n = 1;
  endif
endfunction

## A two-input record: an identified error, or a model with two inputs
## (never the one-input result with the second input ignored).
function n = two_inputs (name, f, data)
  n = 0;
  try
    M = f (data);
  catch err
    if (isempty (regexp (err.identifier, ['^' name ':\w+$'], "once")))
      printf ("  FAIL %s, two inputs: id '%s': %s\n", name, err.identifier,
              err.message);
      n = 1;
    endif
    return;
  end_try_catch
  nu = NaN;
  try
    nu = size (M, 2);
  end_try_catch
  if (! (isobject (M) && nu == 2))
    printf ("  FAIL %s: second input ignored (a %s with %d inputs)\n", name,
            class (M), nu);
    n = 1;
  endif
endfunction

## The call must raise an error with the identifier <name>:<reason>.
function n = expect_error (name, f, what)
  n = 0;
  try
    f ();
  catch err
    if (isempty (regexp (err.identifier, ['^' name ':\w+$'], "once")))
      printf ("  FAIL %s: id '%s': %s\n", what, err.identifier, err.message);
      n = 1;
    endif
    return;
  end_try_catch
  printf ("  FAIL %s: no error\n", what);
  n = 1;
endfunction

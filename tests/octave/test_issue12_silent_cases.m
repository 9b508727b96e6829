## -*- texinfo -*-
## @deftypefn {} {} test_issue12_silent_cases ()
## The "silently wrong answers" of issue 12, each re-checked in one place:
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
## @item @code{idctm (..., "nk", NaN)} (and Inf): an error.
## @end itemize
## @end deftypefn

function test_issue12_silent_cases ()
  root = getenv ("CTID_ROOT");
  if (isempty (root))
    root = fullfile (fileparts (mfilename ("fullpath")), "..", "..");
  endif
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
  if (nfail > 0)
    error ("test_issue12_silent_cases: %d failures", nfail);
  endif
  printf ("test_issue12_silent_cases: every case right or identified\n");
endfunction

function n = check (ok, what)
  n = 0;
  if (! ok)
    printf ("  FAIL %s\n", what);
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

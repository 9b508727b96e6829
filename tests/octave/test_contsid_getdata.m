## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {} test_contsid_getdata ()
## Tests of @file{octave/private/contsid_getdata.m}, the data reader of
## every front-end.  Errors on the first failure, so that CTest can run it:
## @example
## octave --no-gui -q --eval "addpath octave tests/octave; test_contsid_getdata"
## @end example
## The private folder is put on the path for the duration of the test.
## Covers numeric (y, u, Ts) and (y, u, t) data, iddata objects built here
## and by the control package (when installed), irregular sampling,
## InterSample, and every validation branch.
## @end deftypefn

function test_contsid_getdata ()
  root = fileparts (fileparts (fileparts (mfilename ("fullpath"))));
  private_dir = fullfile (root, "octave", "private");
  addpath (fullfile (root, "octave"));
  addpath (private_dir);
  cleanup = onCleanup (@() rmpath (private_dir));

  t = (0:99).' * 0.05;
  y = sin (t);
  u = [sign(sin(3 * t)), cos(t)];

  ## numeric (y, u, Ts); the arguments after the data are not consumed
  d = contsid_getdata ("rlssvf", y, u, 0.05, [2 2 0], "adm", "ff");
  assert (d.y, y);
  assert (d.u, u);
  assert (d.t, t, 1e-15);
  assert (d.Ts, 0.05);
  assert (d.uniform, true);
  assert (d.intersample, "zoh");
  assert (d.nconsumed, 3);
  assert (fieldnames (d), {"y"; "u"; "t"; "Ts"; "uniform"; "intersample";
                           "nconsumed"});

  ## single precision and row vectors become double columns
  d = contsid_getdata ("rlssvf", single (y.'), single (u(:,1).'),
                       single (0.05));
  assert (class (d.y), "double");
  assert (size (d.y), [100, 1]);
  assert (size (d.u), [100, 1]);
  assert (d.y, double (single (y)));
  assert (d.Ts, double (single (0.05)));

  ## numeric (y, u, t): irregular instants, kept as given
  ti = 1 + cumsum ([0; 0.04 + 0.002 * mod((1:99).', 5)]);
  d = contsid_getdata ("rivsvf", y, u, ti);
  assert (d.t, ti);
  assert (isnan (d.Ts));
  assert (d.uniform, false);
  assert (d.nconsumed, 3);

  ## equally spaced instants (up to rounding) are uniform, not shifted
  d = contsid_getdata ("rivsvf", y, u, 2 + t.');
  assert (d.uniform, true);
  assert (d.Ts, 0.05, 1e-14);
  assert (d.t, 2 + t);
  d = contsid_getdata ("rivsvf", y, u, single (1e3 + t));
  assert (d.uniform, true);

  ## our iddata, zoh and foh, regular and irregular
  data = iddata (y, u, 0.05, "InterSample", "foh");
  d = contsid_getdata ("rsrivc", data, [1 2 0], "tsiv", 1);
  assert (d.y, y);
  assert (d.u, u);
  assert (d.t, t, 1e-15);
  assert (d.Ts, 0.05);
  assert (d.intersample, "foh");
  assert (d.nconsumed, 1);
  d = contsid_getdata ("rsrivc", iddata (y, u, ti));
  assert (d.t, ti);
  assert (d.uniform, false);
  ## irregular, InterSample not given: CONTSID's rule from the inputs'
  ## smoothness (u(:, 2) = cos (t) is smooth: linear between the instants;
  ## a held input alone: zoh); a given InterSample is kept
  assert (d.intersample, "foh");
  d = contsid_getdata ("rsrivc", iddata (y, u(:, 1), ti));
  assert (d.intersample, "zoh");
  d = contsid_getdata ("rsrivc", iddata (y, u, ti, "InterSample", "zoh"));
  assert (d.intersample, "zoh");
  ## InterSample and instants survive indexing
  d = contsid_getdata ("rsrivc", iddata (y, u, ti, "InterSample", "foh")(5:20));
  assert (d.t, ti(5:20));
  assert (d.intersample, "foh");
  assert (d.y, y(5:20));

  ## an iddata object built by the control package's own constructor
  if (! isempty (pkg ("list", "control")))
    here = fullfile (root, "octave");
    pkg load control
    rmpath (here);
    unwind_protect
      cdata = iddata (y, u, 0.05);
      assert (! isempty (strfind (which ("iddata"), "control")));
    unwind_protect_cleanup
      addpath (here);
    end_unwind_protect
    d = contsid_getdata ("lssvf", cdata, [2 2 0], 0.5);
    assert (d.y, y);
    assert (d.u, u);
    assert (d.Ts, 0.05);
    assert (d.intersample, "zoh");
    assert (d.nconsumed, 1);
  endif

  ## validation: every branch, its identifier, the argument named
  ok = @(varargin) contsid_getdata ("rlssvf", varargin{:});
  expect_error (@() contsid_getdata (3, y, u, 1),
                "contsid_getdata:badInput", "fname");
  expect_error (@() ok (), "rlssvf:badInput", "'data' is missing");
  expect_error (@() ok (y, u), "rlssvf:badInput", "y, u and Ts");
  expect_error (@() ok ({y}, u, 1), "rlssvf:badInput", "'y'");
  expect_error (@() ok (int16 (y), u, 1), "rlssvf:badInput", "'y'");
  expect_error (@() ok (y, true (100, 1), 1), "rlssvf:badInput", "'u'");
  expect_error (@() ok ([], u, 1), "rlssvf:badInput", "'y' is empty");
  expect_error (@() ok (y, [], 1), "rlssvf:badInput", "'u' is empty");
  expect_error (@() ok (y + 1i, u, 1), "rlssvf:badInput", "'y'.*complex");
  expect_error (@() ok (y, u + 1i, 1), "rlssvf:badInput", "'u'.*complex");
  expect_error (@() ok ([y(1:99); NaN], u, 1), "rlssvf:badInput", "'y'");
  expect_error (@() ok (y, [u(1:99,:); Inf, 0], 1), "rlssvf:badInput",
                "'u'");
  expect_error (@() ok ([y, y], u, 1), "rlssvf:badInput", "single output");
  expect_error (@() ok (y, u(1:99,:), 1), "rlssvf:dimensionMismatch",
                "'u'");
  expect_error (@() ok (y, u, 0), "rlssvf:badInput", "'Ts'");
  expect_error (@() ok (y, u, -0.1), "rlssvf:badInput", "'Ts'");
  expect_error (@() ok (y, u, Inf), "rlssvf:badInput", "'Ts'");
  expect_error (@() ok (y, u, NaN), "rlssvf:badInput", "'Ts'");
  expect_error (@() ok (y, u, "0.1"), "rlssvf:badInput", "'Ts'");
  expect_error (@() ok (y, u, 0.1i), "rlssvf:badInput", "'Ts'");
  expect_error (@() ok (y, u, ones (2)), "rlssvf:badInput", "'Ts'");
  expect_error (@() ok (y, u, t(1:50)), "rlssvf:dimensionMismatch", "'t'");
  expect_error (@() ok (y, u, [t(1:99); NaN]), "rlssvf:badInput", "'t'");
  expect_error (@() ok (y, u, [t(1:98); t(98); 5]), "rlssvf:badInput",
                "'t'.*increasing");
  expect_error (@() ok (y, u, flipud (t)), "rlssvf:badInput", "'t'");
  pair = data;
  pair(2) = data;
  expect_error (@() ok (pair), "rlssvf:badInput", "'data'");
  expect_error (@() ok (iddata ({y, y}, {u, u}, 1)), "rlssvf:badInput",
                "experiments");
  expect_error (@() ok (iddata (y, u, 1, "Frequency", (0:99).')),
                "rlssvf:badInput", "frequency");
  expect_error (@() ok (iddata (y, u)), "rlssvf:badInput",
                "sampling interval");
  expect_error (@() ok (iddata (y, [], 1)), "rlssvf:badInput", "input");
  expect_error (@() ok (iddata (y + 1, u, 1, "y", [y(1:99); NaN])),
                "rlssvf:badInput", "'y'");
  expect_error (@() ok (iddata (int8 (y), u, 1)), "rlssvf:badInput", "'y'");
  expect_error (@() ok (iddata ([y, y], u, 1)), "rlssvf:badInput",
                "single output");
  printf ("test_contsid_getdata: all tests passed\n");
endfunction

## Check that f() raises an error with identifier id and a message that
## matches the regular expression pattern (and starts with the id's
## function name).
function expect_error (f, id, pattern)
  try
    f ();
  catch err
    fname = strtok (id, ":");
    if (! strcmp (err.identifier, id)
        || ! strncmp (err.message, [fname, ":"], numel (fname) + 1)
        || isempty (regexp (err.message, pattern, "once")))
      error ("test_contsid_getdata:failed",
             "expected %s matching /%s/, got %s: %s", id, pattern,
             err.identifier, err.message);
    endif
    return;
  end_try_catch
  error ("test_contsid_getdata:failed", "expected error %s, got none", id);
endfunction

## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {} test_contsid_options ()
## Tests of @file{octave/private/contsid_options.m}, the name-value parser
## of every front-end.  Errors on the first failure, so that CTest can run
## it:
## @example
## octave --no-gui -q --eval "addpath octave tests/octave; test_contsid_options"
## @end example
## The private folder is put on the path for the duration of the test.
## @end deftypefn

function test_contsid_options ()
  root = fileparts (fileparts (fileparts (mfilename ("fullpath"))));
  private_dir = fullfile (root, "octave", "private");
  addpath (private_dir);
  cleanup = onCleanup (@() rmpath (private_dir));

  defaults = struct ("adm", "ff", "adg", 1, "lambda_svf", [], "P0", 1e4,
                     "th0", {{}});

  ## no options: the defaults, nothing given
  opts = contsid_options ("rlssvf", defaults, {});
  assert (rmfield (opts, "given_"), defaults);
  assert (opts.given_, cell (1, 0));
  opts = contsid_options ("rlssvf", defaults);
  assert (rmfield (opts, "given_"), defaults);

  ## name-value pairs, names ignoring case, canonical names in given_
  opts = contsid_options ("rlssvf", defaults,
                          {"ADM", "kf", "p0", 10, "Lambda_SVF", 2});
  assert (opts.adm, "kf");
  assert (opts.P0, 10);
  assert (opts.lambda_svf, 2);
  assert (opts.adg, 1);
  assert (opts.th0, {});
  assert (opts.given_, {"adm", "P0", "lambda_svf"});
  assert (! isfield (opts, "ADM") && ! isfield (opts, "p0"));

  ## a later value wins; a name is listed once
  opts = contsid_options ("rlssvf", defaults, {"adg", 0.9, "ADG", 0.95});
  assert (opts.adg, 0.95);
  assert (opts.given_, {"adg"});

  ## cell values stay cells
  opts = contsid_options ("rlssvf", defaults, {"th0", {1, 2}});
  assert (opts.th0, {1, 2});

  ## a struct of options, alone, in a cell, or followed by pairs
  opts = contsid_options ("rivsvf", defaults, struct ("Adm", "kf"));
  assert (opts.adm, "kf");
  assert (opts.given_, {"adm"});
  opts = contsid_options ("rivsvf", defaults,
                          {struct("adm", "kf", "adg", 2), "adg", 3});
  assert (opts.adm, "kf");
  assert (opts.adg, 3);
  assert (opts.given_, {"adm", "adg"});

  ## errors: identifier <fname>:badOption, message names the key
  expect_error (@() contsid_options ("rlssvf", defaults, {"bogus", 1}),
                "rlssvf:badOption", "'bogus'");
  expect_error (@() contsid_options ("rlssvf", defaults, {"ad", 1}),
                "rlssvf:badOption", "'ad'");
  expect_error (@() contsid_options ("rlssvf", defaults, {"adm"}),
                "rlssvf:badOption", "'adm' has no value");
  expect_error (@() contsid_options ("rlssvf", defaults,
                                     {"adm", "kf", "adg"}),
                "rlssvf:badOption", "'adg' has no value");
  expect_error (@() contsid_options ("rlssvf", defaults, {3, 1}),
                "rlssvf:badOption", "argument 1");
  expect_error (@() contsid_options ("rlssvf", defaults, {"adm", 1, {}, 2}),
                "rlssvf:badOption", "argument 3");
  expect_error (@() contsid_options ("rlssvf", defaults,
                                     {["ab"; "cd"], 1}),
                "rlssvf:badOption", "argument 1");
  expect_error (@() contsid_options ("rlssvf", defaults,
                                     struct ("Bogus", 1)),
                "rlssvf:badOption", "'Bogus'");
  expect_error (@() contsid_options ("rlssvf", defaults,
                                     {struct("adm", {"ff", "kf"})}),
                "rlssvf:badOption", "scalar");

  ## errors in the caller's own use (programming errors)
  expect_error (@() contsid_options (3, defaults, {}),
                "contsid_options:badInput", "fname");
  expect_error (@() contsid_options ("rlssvf"),
                "contsid_options:badInput", "fname");
  expect_error (@() contsid_options ("rlssvf", struct ("a", 1, "A", 2), {}),
                "contsid_options:badInput", "defaults");
  expect_error (@() contsid_options ("rlssvf", struct ("given_", 1), {}),
                "contsid_options:badInput", "defaults");
  expect_error (@() contsid_options ("rlssvf", struct ("a", {1, 2}), {}),
                "contsid_options:badInput", "defaults");
  expect_error (@() contsid_options ("rlssvf", 3, {}),
                "contsid_options:badInput", "defaults");
  expect_error (@() contsid_options ("rlssvf", defaults, "adm"),
                "contsid_options:badInput", "args");
  printf ("test_contsid_options: all tests passed\n");
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
      error ("test_contsid_options:failed",
             "expected %s matching /%s/, got %s: %s", id, pattern,
             err.identifier, err.message);
    endif
    return;
  end_try_catch
  error ("test_contsid_options:failed", "expected error %s, got none", id);
endfunction

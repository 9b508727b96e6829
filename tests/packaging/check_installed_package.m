## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {} check_installed_package (@var{prefix}, @var{src})
## Run by test_octave_package.sh in a fresh Octave session after
## @code{pkg install}: loads the package installed under @var{prefix} and
## checks that every function comes from there (not from the source tree
## @var{src}), that PKG_ADD put our @code{iddata} in front of the control
## package's, that CONTSID calls run through the compiled gateways and
## recover a known system, and that the inline tests of a few functions
## pass in the installed copy.  Errors on the first failure.
## @end deftypefn

function check_installed_package (prefix, src)
  pkg load ctid
  pkgdir = pkg ("list", "ctid"){1}.dir;
  assert (strncmp (pkgdir, prefix, numel (prefix)),
          "ctid was loaded from %s, not from %s", pkgdir, prefix);
  for f = {"srivc", "rlssvf", "rsrivc", "simc", "prbs", "iddata"}
    w = which (f{1});
    assert (strncmp (w, pkgdir, numel (pkgdir)), "%s comes from %s", f{1},
            w);
    assert (isempty (strfind (w, src)), "%s comes from the source tree", f{1});
  endfor
  ## Every gateway of the source tree was compiled at install time, beside
  ## the private functions that call them.
  sources = dir (fullfile (src, "mex", "*_mex.cpp"));
  assert (numel (sources) > 0);
  for k = 1:numel (sources)
    [~, g] = fileparts (sources(k).name);
    assert (isfile (fullfile (pkgdir, "private", [g ".mex"])),
            "gateway %s is missing", g);
  endfor
  ## The gateways a class's methods call (CTID_CLASS_GATEWAYS of
  ## mex/CMakeLists.txt), in the class's private folder too.
  cmake = fileread (fullfile (src, "mex", "CMakeLists.txt"));
  entries = regexp (cmake, 'set\(CTID_CLASS_GATEWAYS ([^)]*)\)', "tokens",
                    "once");
  assert (! isempty (entries));
  for e = strsplit (strtrim (entries{1}))
    cg = strsplit (e{1}, ":");
    assert (isfile (fullfile (pkgdir, ["@" cg{1}], "private", [cg{2} ".mex"])),
            "gateway %s of class %s is missing", cg{2}, cg{1});
  endfor
  ## PKG_ADD: with the control package installed, ours comes first.
  if (! isempty (pkg ("list", "control")))
    assert (strcmp (which ("iddata"),
                    fullfile (pkgdir, "@iddata", "iddata.m")));
  endif

  ## CONTSID calls on the system of the rlssvf tests, G(s) = 4/(s^2+2.4s+4).
  Ts = 0.05;
  u = prbs (9, 8);
  y = simc (struct ("B", 4, "F", [1 2.4 4]), u, Ts);
  data = iddata (y, u, Ts, "InterSample", "zoh");
  M = srivc (data, [1 2 0], "lambda", 3, "Tol", 1e-12);   # [nb nf nk]
  printf ("srivc: F = %s, B = %s\n", mat2str (M.F, 8), mat2str (M.B, 8));
  assert (M.F, [1 2.4 4], 1e-8);     # noise-free: exact (see help srivc)
  assert (M.B, 4, 1e-8);
  ## a class method through its private gateway: the final value of the
  ## step response is the static gain
  assert (step (M, [0; 40])(end), 1, 1e-6);
  thm = rlssvf (data, [2 1 0], "lambda_svf", 3);
  printf ("rlssvf: final [a1 a2 b0] = %s\n", mat2str (thm(end, :), 6));
  assert (thm(end, :), [2.4 4 4], 2e-3 * 4);
  thm = rsrivc (data, [1 2 0], "lambda_svf", 3);
  assert (thm(end, :), [4 2.4 4], 2e-3 * 4);   # [b f] order
  ## An identified error through the gateway's options struct.
  try
    rlssvf (data, [2 1 0], "lambda_svf", -1);
    error ("check_installed_package: no error for lambda_svf < 0");
  catch err
    assert (strncmp (err.identifier, "rlssvf:", 7), err.identifier);
  end_try_catch

  ## The inline tests (%!test, %!error) of a few functions, run in the
  ## installed copy (Octave 7 has no "pkg test"; see the README).
  for f = {"prbs", "simc", "rlssvf", "srivc", "@iddata/iddata"}
    [n, nmax] = test (f{1}, "quiet");
    printf ("test %s: %d of %d passed\n", f{1}, n, nmax);
    assert (nmax > 0 && n == nmax, "inline tests of %s failed", f{1});
  endfor
endfunction

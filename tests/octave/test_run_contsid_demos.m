## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {} test_run_contsid_demos ()
## @file{scripts/run-contsid-demos} on demos written here (CONTSID's own are
## not in the repository): one that calls the interactive functions the
## script makes no-ops (pause, clc, keyboard, input) between toolbox calls
## runs to its end; one that calls a function nobody has, and one that
## calls menu (a launcher), are reported with their first error; the count
## line says 1 of 3.
## @end deftypefn

function test_run_contsid_demos ()
  root = ctid_test_root ();
  dir = tempname ();
  mkdir (dir);
  cleanup = onCleanup (@() remove_dir (dir));
  write (fullfile (dir, "contsid_fake_ok.m"),
         {"pause", "clc", "x = input ('go? ');", "keyboard", ...
          "u = prbs (8, 4); Ts = 0.05;", ...
          "y = simc (idpoly (1, 4, 1, 1, [1 2.4 4], 'Ts', 0), u, Ts);", ...
          "M = srivc (iddata (y, u, Ts), [1 2 0]);", ...
          "assert (M.F, [1 2.4 4], 1e-6);"});
  write (fullfile (dir, "contsid_fake_missing.m"),
         {"pause", "no_such_function_anywhere (1)"});
  write (fullfile (dir, "contsid_fake_menu.m"),
         {"k = menu ('CONTSID demos', 'one', 'Quit');"});
  [status, out] = system (sprintf ("bash '%s' '%s'",
                                   fullfile (root, "scripts",
                                             "run-contsid-demos"), dir));
  printf ("%s", out);
  assert (status, 0);
  assert (! isempty (regexp (out, "contsid_fake_ok +ran to its end", "once")));
  assert (! isempty (regexp (out, ["contsid_fake_missing +", ...
    "Octave:undefined-function: 'no_such_function_anywhere' undefined"],
    "once")));
  assert (! isempty (regexp (out, "contsid_fake_menu +run_contsid_demos:menu",
                             "once")));
  assert (! isempty (strfind (out, "1 of 3 demos ran to their end")));
endfunction

function remove_dir (dir)
  confirm_recursive_rmdir (false, "local");
  rmdir (dir, "s");
endfunction

function write (file, lines)
  fid = fopen (file, "w");
  fprintf (fid, "%s\n", lines{:});
  fclose (fid);
endfunction

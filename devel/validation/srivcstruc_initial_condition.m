## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## srivcstruc_initial_condition: the structure chosen on 8 simulated
## Cascaded Tanks record pairs (4 draws, nominal and strong excitation) by
## srivcstruc's validation R_T^2 from rest ("InitialCondition", "z", the
## default) and with each model's initial state estimated ("e"), under the
## two rules of the residtrace studies (the best R_T^2, and
## parsimonious_structure). Prints one line per pair; about a minute.
## Run from the repository root:
##   devel/run-study srivcstruc_initial_condition

function srivcstruc_initial_condition ()
  root = fileparts (fileparts (fileparts (mfilename ("fullpath"))));
  addpath (fullfile (root, "octave"));
  addpath (fullfile (root, "demos"));
  pkg load control;
  NN = [1 1 0; 1 2 0; 2 2 0; 1 3 0; 2 3 0; 3 3 0; 1 1 1; 1 2 1];
  for variant = {"nominal", "strong"}
    for d = 1:4
      [de, dv] = cascaded_tanks_sim ("records", d, variant{1});
      ws = warning ("off", "all");
      Vz = srivcstruc (de, dv, NN, "NN", "list");
      Ve = srivcstruc (de, dv, NN, "NN", "list", "InitialCondition", "e");
      warning (ws);
      bz = selcstruc (Vz, "c2sort", "RT2")(1, :);
      be = selcstruc (Ve, "c2sort", "RT2")(1, :);
      printf (["%s %d | best z [%s] e [%s] | simplest z [%s] e [%s] | ", ...
               "RT2 z %s | e %s\n"], variant{1}, d, num2str (bz),
              num2str (be), num2str (parsimonious_structure (Vz)),
              num2str (parsimonious_structure (Ve)), mat2str (Vz(:,1)', 2),
              mat2str (Ve(:,1)', 2));
      fflush (stdout);
    endfor
  endfor
endfunction

## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## The measured-data demos of residtrace run on reduced
## settings and write their figures and tables. Sanity of what they find:
## on the EMPS the Coulomb friction (about 20 N in the benchmark's own
## identification; here within the range an independent inverse-dynamic
## fit of the same record allows) and a lower validation error; on the
## Silverbox a lower validation error than the LTI model's. The grey-box
## demo (simulated rigs, no data needed): on the two tanks the overflow (a
## saturation, or the input clipped) or the square-root outflows (a state
## nonlinearity) named first and a validation simulation error well below
## the best linear model's; on the axis the end stops (saturation).
function test_residtrace_demos ()
  run_demo_test (@check);
endfunction

function check (out, root)
  G = demo_greybox (out, true);
  for f = {"greybox.md", "fig_greybox_tanks.png", "fig_greybox_axis.png"}
    assert (exist (fullfile (out, f{1}), "file") == 2);
  endfor
  ## the overflow as a saturation of an inner node or of the output, or
  ## as the input clipped (what an overflowing upper tank does to the flow
  ## into the lower one), or the square-root outflow
  r = G.tanks.R;
  over = any (strcmp (r.effect, {"saturation", "state_nonlinearity"})) ...
         || (strcmp (r.effect, "static_nonlinearity")
             && any (strcmp (channel_types (r.model), "clip")));
  assert (over);
  assert (G.tanks.R.rmse_final < 0.5 * G.tanks.rmse_linear);
  assert (G.axis.R.effect, "saturation");
  assert (G.axis.R.rmse_final < G.axis.rmse_linear);

  ## the measured records (CTID_DATA, default ../shared/data): without
  ## them the grey-box part above has run and the test reports itself as
  ## skipped, with the reason
  [data, why] = ctid_data_dir ();
  if (isempty (data))
    ctid_test_skip (why);
  endif
  R = demo_emps (out, true);
  for f = {"emps.md", "fig_emps_sim.png", "fig_emps_resid.png", ...
           "fig_emps_segments.png"}
    assert (exist (fullfile (out, f{1}), "file") == 2);
  endfor
  assert (R.effect, "coulomb");
  assert (R.rmse_after < 0.5 * R.rmse_before);
  k = strcmp ({R.params_after.name}, "Coulomb level -b_s/b0");
  Fc = R.params_after(k).value;
  assert (Fc > 10 && Fc < 30);
  md = fileread (fullfile (out, "emps.md"));
  assert (! isempty (strfind (md, "| + coulomb")));

  R = demo_silverbox (out, true);
  for f = {"silverbox.md", "fig_silverbox_track.png", ...
           "fig_silverbox_sim.png", "fig_silverbox_resid.png"}
    assert (exist (fullfile (out, f{1}), "file") == 2);
  endfor
  assert (! strcmp (R.effect, "none"));
  assert (R.rmse_after < R.rmse_refit);
endfunction

## The types of a residtrace model's channels (M.channels is a struct
## array: read it before listing a field, see help idtraced/subsref).
function t = channel_types (M)
  ch = M.channels;
  t = {ch.type};
endfunction

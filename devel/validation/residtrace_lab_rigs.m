## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{S} =} residtrace_lab_rigs ()
## @deftypefnx {} {@var{S} =} residtrace_lab_rigs (@var{outdir}, @var{rigs}, @var{rule}, @var{draw})
## A check of @code{residtrace} on records made apart from it: on the
## records of @code{lab_rigs} (five nonlinear simulated lab rigs, three
## linear ones, written from the help texts alone of
## @code{residtrace}, @code{residtrace_table}, @code{srivc} and
## @code{iddata}, not residtrace's code), does @code{residtrace} name the
## documented effect first, and no nonlinear effect on a linear rig?
##
## For each rig, as a user would: the structures of @code{rig.NN} fitted
## by @code{srivcstruc} on the estimation record and judged by their
## validation R_T^2; of those whose validation residual variance
## (1 - R_T^2) is within 10 % of the smallest, the one with the fewest
## parameters, fitted by @code{srivc} on the raw estimation record, then
## @code{R = residtrace (de, M, "validation", dv)} with its defaults.  An
## error of residtrace is a finding: it is caught and reported.
##
## Nonlinear effects: coulomb, static_nonlinearity, saturation,
## state_nonlinearity.  Verdict of a nonlinear rig: "right" when
## R.effect is the documented effect, else "miss"; of a linear rig:
## "right" when neither R.effect nor R.effects holds a nonlinear effect,
## else "false alarm".
##
## Writes @var{outdir}/lab_rigs.md (default "results"): the summary table,
## each rig's structure table and residtrace's own table
## (@code{R.table}).  @var{rigs}: a cell of rig names (default all).
## @var{rule}: the user's choice of structure, "simplest" (default, as
## above) or "best" (the best validation R_T^2, @code{selcstruc (V,
## "c2sort", "RT2")}: the sensitivity of the verdicts to that choice).
## @var{draw}: the random draw of the records (default 0; see
## @code{lab_rigs}).
## @var{S}: struct array of the figures.
## @end deftypefn

function S = residtrace_lab_rigs (outdir, rigs, rule, draw)
  if (nargin < 1 || isempty (outdir))
    outdir = "results";
  endif
  if (nargin < 2 || isempty (rigs))
    rigs = lab_rigs ();
  endif
  if (nargin < 3 || isempty (rule))
    rule = "simplest";
  endif
  if (! any (strcmp (rule, {"simplest", "best"})))
    error ("residtrace_lab_rigs:badOption", "residtrace_lab_rigs: rule '%s'",
           rule);
  endif
  if (nargin < 4 || isempty (draw))
    draw = 0;
  endif
  here = fileparts (mfilename ("fullpath"));
  addpath (fullfile (here, "..", "..", "octave"));
  addpath (here);
  nonlinear = {"coulomb", "static_nonlinearity", "saturation", ...
               "state_nonlinearity"};
  S = struct ([]);
  for i = 1:numel (rigs)
    rig = lab_rigs (rigs{i}, 1, draw);
    s = run_rig (rig, nonlinear, rule);
    printf ("%-13s %-19s named %-19s all {%s}  %.4g -> %.4g  %.1f s  %s\n",
            s.name, s.effect, s.named, strjoin (s.all, ", "),
            s.rmse_before, s.rmse_final, s.seconds, s.verdict);
    if (isempty (S))
      S = s;
    else
      S(end+1) = s;
    endif
  endfor
  if (! exist (outdir, "dir"))
    mkdir (outdir);
  endif
  write_report (S, fullfile (outdir, "lab_rigs.md"), rule);
endfunction

function s = run_rig (rig, nonlinear, rule)
  s.name = rig.name;
  s.title = rig.title;
  s.kind = rig.kind;
  s.effect = rig.effect;
  s.physics = rig.physics;
  s.N = [numel(rig.de.y), numel(rig.dv.y)];
  s.Ts = rig.Ts;
  ## The user's linear model: the structures of rig.NN by validation fit.
  ws = warning ("off", "all");
  [V, vinfo] = srivcstruc (rig.de, rig.dv, rig.NN, "NN", "list");
  warning (ws);
  s.V = V;
  s.vfit = vinfo.fit;
  s.nn_best = selcstruc (V, "c2sort", "RT2")(1,:);
  if (strcmp (rule, "best"))
    s.nn = s.nn_best;
  else
    s.nn = parsimonious_structure (V);
  endif
  s.rule = rule;
  lastwarn ("");
  [M, ~, ~, ~, ~, info] = srivc (rig.de, s.nn);
  [msg, id] = lastwarn ();
  s.srivc_warning = id;
  s.srivc_reason = info.reason;
  s.error = "";
  s.named = "";
  s.all = {};
  s.rmse_given = s.rmse_before = s.rmse_after = s.rmse_final = NaN;
  s.verdict_text = "";
  s.levels = "";
  s.ranking = "";
  s.table = "";
  t0 = tic ();
  c0 = cputime ();
  try
    R = residtrace (rig.de, M, "validation", rig.dv);
    s.seconds = toc (t0);
    s.cpu = cputime () - c0;
    s.named = R.effect;
    s.all = effect_names (R.effects);
    s.rmse_given = R.rmse_given;
    s.rmse_before = R.rmse_before;
    s.rmse_after = R.rmse_after;
    s.rmse_final = R.rmse_final;
    s.verdict_text = R.verdict;
    if (isfield (R, "levels") && isstruct (R.levels) ...
        && isfield (R.levels, "text"))
      s.levels = R.levels.text;
    endif
    s.ranking = ranking_lines (R.ranking);
    s.table = R.table;
  catch err
    s.seconds = toc (t0);
    s.cpu = cputime () - c0;
    s.error = sprintf ("%s: %s", err.identifier, err.message);
    s.named = "(error)";
  end_try_catch
  named_nl = any (strcmp (s.named, nonlinear)) ...
             || any (ismember (s.all, nonlinear));
  if (! isempty (s.error))
    s.verdict = "error";
  elseif (strcmp (s.kind, "nonlinear"))
    if (strcmp (s.named, s.effect))
      s.verdict = "right";
    else
      s.verdict = "miss";
    endif
  else
    if (named_nl)
      s.verdict = "false alarm";
    else
      s.verdict = "right";
    endif
  endif
endfunction

## The first five candidates of the first pass, one line each.
function t = ranking_lines (rk)
  t = "";
  for j = 1:min (5, numel (rk))
    r = rk(j);
    v = "";
    if (isfield (r, "variant") && ischar (r.variant))
      v = r.variant;
    endif
    g = "";
    if (isfield (r, "group") && ischar (r.group))
      g = r.group;
    endif
    t = [t, sprintf("| %s | %s | %s | %.4f | %.3g | %d |\n", r.effect, g, ...
                    v, r.score, r.p, r.significant)];
  endfor
endfunction

function write_report (S, file, rule)
  fid = fopen (file, "w");
  if (fid < 0)
    error ("residtrace_lab_rigs:badInput",
           "residtrace_lab_rigs: cannot write %s", file);
  endif
  fprintf (fid, "# residtrace on simulated lab rigs\n\n");
  fprintf (fid, ["Records made by devel/validation/lab_rigs.m (simulated lab ", ...
                 "rigs, raw units, sensor noise and quantisation); model: ", ...
                 "srivc with the structure of rule '%s' (simplest: the ", ...
                 "fewest parameters among those whose validation residual ", ...
                 "variance 1 - R_T^2 (srivcstruc) is within 10 %% of the ", ...
                 "smallest; best: the best R_T^2); then ", ...
                 "residtrace (de, M, ", ...
                 "\"validation\", dv) with its defaults. RMSE: validation ", ...
                 "simulation (R.rmse_given, R.rmse_before, R.rmse_final).", ...
                 "\n\n"], rule);
  fprintf (fid, ["| rig | kind | documented effect | structure | named ", ...
                 "first | all named | RMSE given | RMSE before | RMSE ", ...
                 "after (final) | time (s) | CPU (s) | verdict |\n"]);
  fprintf (fid, "|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  for i = 1:numel (S)
    s = S(i);
    fprintf (fid, ["| %s | %s | %s | [%s] | %s | %s | %.4g | %.4g | ", ...
                   "%.4g | %.1f | %.1f | %s |\n"],
             s.name, s.kind, s.effect, num2str (s.nn), s.named,
             strjoin (s.all, ", "), s.rmse_given, s.rmse_before,
             s.rmse_final, s.seconds, s.cpu, s.verdict);
  endfor
  nl = strcmp ({S.kind}, "nonlinear");
  ok = strcmp ({S.verdict}, "right");
  fprintf (fid, ["\nNonlinear rigs named right first: %d of %d; linear ", ...
                 "rigs without a nonlinear effect: %d of %d.\n"],
           sum (nl & ok), sum (nl), sum (! nl & ok), sum (! nl));
  for i = 1:numel (S)
    s = S(i);
    fprintf (fid, "\n## %s: %s\n\n", s.name, s.title);
    fprintf (fid, ["Physics: %s. Documented effect: %s. Records: %d / %d ", ...
                   "samples, Ts = %g s.\n\n"],
             s.physics, s.effect, s.N(1), s.N(2), s.Ts);
    fprintf (fid, "Structures (srivcstruc, validation R_T^2):\n\n");
    fprintf (fid, "| nn | RT2 (validation) | fit %% |\n|---|---|---|\n");
    for j = 1:rows (s.V)
      nn = s.V(j, 3:end-2);
      fprintf (fid, "| [%s] | %.4f | %.1f |\n", num2str (nn), s.V(j,1),
               s.vfit(j));
    endfor
    fprintf (fid, ["\nChosen [%s] (best R_T^2: [%s]); srivc: %s %s", ...
                   "\n\n"], num2str (s.nn), num2str (s.nn_best),
             s.srivc_reason, s.srivc_warning);
    if (! isempty (s.error))
      fprintf (fid, "residtrace raised an error: %s\n", s.error);
      continue;
    endif
    fprintf (fid, "Verdict of residtrace: %s\n\nLevels: %s\n\n",
             s.verdict_text, s.levels);
    fprintf (fid, "Time: %.1f s wall, %.1f s CPU.\n\n", s.seconds, s.cpu);
    fprintf (fid, "First pass, top five:\n\n");
    fprintf (fid, "| effect | group | variant | score | p | significant |\n");
    fprintf (fid, "|---|---|---|---|---|---|\n%s\n", s.ranking);
    fprintf (fid, "residtrace's table:\n\n%s\n", s.table);
  endfor
  fclose (fid);
endfunction

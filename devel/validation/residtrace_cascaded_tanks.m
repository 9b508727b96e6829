## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn  {} {@var{S} =} residtrace_cascaded_tanks ()
## @deftypefnx {} {@var{S} =} residtrace_cascaded_tanks (@var{outdir}, @var{draws}, @var{greybox}, @var{rule}, @var{variant})
## residtrace on simulated records of the Cascaded Tanks benchmark
## (@code{cascaded_tanks_sim}): does the linear model plus what
## @code{residtrace} traces reach a validation simulation RMSE well below
## the best linear model's (published for the real benchmark: best linear
## approximation 0.76 V, good black-box nonlinear models 0.34-0.45 V)?
##
## For each random draw of the records (two realisations of the
## multisine, 1024 samples each at Ts = 4 s, raw volts), as a user would
## (the rule of @code{residtrace_lab_rigs}): the structures @var{NN} fitted
## by @code{srivcstruc} on the estimation record and judged by their
## validation R_T^2; of those whose validation residual variance
## (1 - R_T^2) is within 10 % of the smallest, the one with the fewest
## parameters, fitted by @code{srivc} on the raw estimation record; its
## validation simulation RMSE from rest (with srivc's estimated offsets)
## and with the initial state estimated on the validation record
## (@code{comparec} with @code{"InitialCondition", "e"}); then
## @code{R = residtrace (de, M, "validation", dv)} with its defaults
## (timed: wall and CPU). With @var{greybox} (default true) the right
## physics is also fitted: the simulator's parameters k1..k4, frac, x1max
## and the initial levels by Levenberg-Marquardt on the estimation
## record's simulation error (started 20-25 % off the true values; the
## lower rim x2max = 10 V, the sensor's range, is known), scored on the
## validation record from the same estimated initial levels (both records
## start from the same state).
##
## Writes @var{outdir}/cascaded_tanks.md (default "results"): the summary
## table, and per draw the structure table, residtrace's ranking of each
## pass (every candidate: score, p, variant, RMSE, reason) and its
## warnings. @var{draws}: vector of draw numbers (default 1:4).
## @var{rule}: the user's choice of structure, "simplest" (default, as
## above) or "best" (the best validation R_T^2, @code{selcstruc (V,
## "c2sort", "RT2")}: the sensitivity of the figures to that choice; the
## report is then cascaded_tanks_best.md). @var{variant}: the simulator's
## excitation, "nominal" (default) or "strong" (see
## @code{cascaded_tanks_sim}; reports cascaded_tanks_strong*.md).
## @var{greybox} may also be a vector of the draws that get the grey-box
## fit.
## @var{S}: struct array of the figures.
## @end deftypefn

function S = residtrace_cascaded_tanks (outdir, draws, greybox, rule, variant)
  if (nargin < 1 || isempty (outdir))
    outdir = "results";
  endif
  if (nargin < 2 || isempty (draws))
    draws = 1:4;
  endif
  if (nargin < 3 || isempty (greybox))
    greybox = true;
  endif
  if (nargin < 4 || isempty (rule))
    rule = "simplest";
  endif
  if (nargin < 5 || isempty (variant))
    variant = "nominal";
  endif
  if (! any (strcmp (rule, {"simplest", "best"})))
    error ("residtrace_cascaded_tanks:badOption",
           "residtrace_cascaded_tanks: rule '%s'", rule);
  endif
  here = fileparts (mfilename ("fullpath"));
  addpath (fullfile (here, "..", "..", "octave"));
  addpath (here);
  pkg load control;
  ## The structures a user would try on a two-tank level record.
  NN = [1 1 0; 1 2 0; 2 2 0; 1 3 0; 2 3 0; 3 3 0; 1 1 1; 1 2 1];
  S = struct ([]);
  for d = draws(:).'
    if (islogical (greybox))
      g = greybox;
    else
      g = any (greybox == d);
    endif
    s = run_draw (d, NN, g, rule, variant);
    printf (["draw %d [%s]: BLA %.3f V (rest) %.3f V (x0); residtrace ", ...
             "{%s} given %.3f before %.3f final %.3f V; grey-box %.3f V; ", ...
             "%.0f s wall, %.0f s CPU\n"], d, num2str (s.nn),
            s.rmse_bla_rest, s.rmse_bla_x0, strjoin (s.all, ", "),
            s.rmse_given, s.rmse_before, s.rmse_final, s.rmse_grey,
            s.seconds, s.cpu);
    fflush (stdout);
    if (isempty (S))
      S = s;
    else
      S(end+1) = s;
    endif
  endfor
  if (! exist (outdir, "dir"))
    mkdir (outdir);
  endif
  name = "cascaded_tanks";
  if (strcmp (variant, "strong"))
    name = [name, "_strong"];
  endif
  if (strcmp (rule, "best"))
    name = [name, "_best"];
  endif
  name = [name, ".md"];
  write_report (S, NN, fullfile (outdir, name), rule, variant);
endfunction

function s = run_draw (d, NN, greybox, rule, variant)
  [de, dv, truth] = cascaded_tanks_sim ("records", d, variant);
  s.draw = d;
  s.overflow = [sum(truth.top1e), sum(truth.top2e), sum(truth.top1v), ...
                sum(truth.top2v)];
  yv = get (dv, "y");
  uv = get (dv, "u");
  Ts = get (dv, "Ts");
  ## Noise floor: the validation output against its noise-free value.
  s.rmse_noise = rms_ (yv - truth.yv0);
  ## The user's linear model.
  ws = warning ("off", "all");
  [V, vinfo] = srivcstruc (de, dv, NN, "NN", "list");
  warning (ws);
  s.V = V;
  if (strcmp (rule, "best"))
    s.nn = selcstruc (V, "c2sort", "RT2")(1,:);
  else
    s.nn = parsimonious_structure (V);
  endif
  lastwarn ("");
  [M, ~, ~, ~, ~, info] = srivc (de, s.nn);
  [~, id] = lastwarn ();
  s.srivc_warning = id;
  s.srivc_reason = info.reason;
  s.M = M;
  c = 0;
  if (isfield (info, "offset") && isnumeric (info.offset)
      && ! isempty (info.offset))
    c = info.offset;
  endif
  du = 0;
  if (isfield (info, "input_offset") && isnumeric (info.input_offset)
      && ! isempty (info.input_offset))
    du = info.input_offset(1);
  endif
  s.offsets = [du, c];
  ## Its validation simulation from rest, with srivc's offsets ...
  ys = simc (M, uv + du, Ts) + c;
  s.rmse_bla_rest = rms_ (yv - ys);
  ## ... and with its initial state estimated on the validation record
  ## (as MATLAB's compare does by default).
  try
    [ys2, ei] = comparec (iddata (yv - c, uv + du, Ts, "InterSample", ...
                                  "zoh"), M, "InitialCondition", "e");
    s.rmse_bla_x0 = rms_ (yv - c - ys2);
  catch err
    s.rmse_bla_x0 = NaN;
    s.bla_x0_error = err.message;
  end_try_catch
  ## residtrace with its defaults; its warnings are kept.
  s.error = "";
  s.named = "";
  s.all = {};
  s.rmse_given = s.rmse_before = s.rmse_after = s.rmse_final = NaN;
  s.verdict = "";
  s.levels = "";
  s.passes = "";
  s.log = "";
  t0 = tic ();
  c0 = cputime ();
  try
    R = [];
    s.log = evalc ("R = residtrace (de, M, \"validation\", dv);");
    s.seconds = toc (t0);
    s.cpu = cputime () - c0;
    s.named = R.effect;
    s.all = effect_names (R.effects);
    s.rmse_given = R.rmse_given;
    s.rmse_before = R.rmse_before;
    s.rmse_after = R.rmse_after;
    s.rmse_final = R.rmse_final;
    s.verdict = R.verdict;
    if (isfield (R, "levels") && isstruct (R.levels)
        && isfield (R.levels, "text"))
      s.levels = R.levels.text;
    endif
    s.passes = pass_tables (R);
    s.table = R.table;
  catch err
    s.seconds = toc (t0);
    s.cpu = cputime () - c0;
    s.error = sprintf ("%s: %s", err.identifier, err.message);
    s.named = "(error)";
    s.table = "";
  end_try_catch
  ## The right physics.
  s.rmse_grey = NaN;
  s.rmse_grey_est = NaN;
  s.grey = [];
  if (greybox)
    [s.rmse_grey, s.rmse_grey_est, s.grey] = greybox_fit (de, dv, truth.p);
  endif
endfunction

## Grey-box fit: the simulator's own equations, parameters
## th = [k1 k2 k3 k4 frac x1max x10 x20] (log-parametrised; frac through
## a logistic), Levenberg-Marquardt on the estimation record's simulation
## error with forward-difference Jacobians; 8 sub-steps per sample in the
## fit, 40 in the final scoring.
function [rv, re, g] = greybox_fit (de, dv, p0)
  ye = get (de, "y"); ue = get (de, "u");
  yv = get (dv, "y"); uv = get (dv, "u");
  Ts = get (de, "Ts");
  tru = [p0.k1 p0.k2 p0.k3 p0.k4 p0.frac p0.x1max p0.x0(:).'];
  start = tru .* [1.25 0.8 1.2 0.8 1 0.9 1.2 0.8];
  start(5) = 0.3;
  z = to_z (start);
  pf = p0;
  pf.substeps = 8;
  pf.sigma = 0; pf.q = 0; pf.yrange = [-Inf Inf];
  res = @(z) sim_z (z, ue, Ts, pf) - ye;
  r = res (z);
  J = zeros (numel (r), numel (z));
  mu = 1e-2;
  for it = 1:25
    for j = 1:numel (z)
      dz = zeros (size (z));
      dz(j) = 1e-4;
      J(:,j) = (res (z + dz) - r) / 1e-4;
    endfor
    A = J.' * J;
    gvec = J.' * r;
    improved = false;
    for k = 1:8
      ## (a parameter the record does not excite, e.g. the rim of a tank
      ## that never overflows, has a zero column: the floor keeps the
      ## damped system regular and that parameter where it is)
      step = -(A + mu * diag (diag (A) + 1e-6 * max (diag (A)))) \ gvec;
      r2 = res (z + step.');
      if (sum (r2 .^ 2) < sum (r .^ 2))
        z = z + step.';
        rel = 1 - sum (r2 .^ 2) / sum (r .^ 2);
        r = r2;
        mu = max (mu / 3, 1e-8);
        improved = true;
        break;
      endif
      mu *= 4;
    endfor
    if (! improved || rel < 1e-7)
      break;
    endif
  endfor
  th = from_z (z);
  pe = p0;
  pe.k1 = th(1); pe.k2 = th(2); pe.k3 = th(3); pe.k4 = th(4);
  pe.frac = th(5); pe.x1max = th(6); pe.x0 = th(7:8).';
  pe.sigma = 0; pe.q = 0; pe.yrange = [-Inf Inf];
  re = rms_ (cascaded_tanks_sim (ue, Ts, pe) - ye);
  rv = rms_ (cascaded_tanks_sim (uv, Ts, pe) - yv);
  g.theta = th;
  g.true = tru;
  g.start = start;
  g.iterations = it;
endfunction

function z = to_z (th)
  z = log (th);
  z(5) = log (th(5) / (1 - th(5)));
endfunction

function th = from_z (z)
  th = exp (z);
  th(5) = 1 / (1 + exp (-z(5)));
endfunction

function y = sim_z (z, u, Ts, p)
  th = from_z (z);
  p.k1 = th(1); p.k2 = th(2); p.k3 = th(3); p.k4 = th(4);
  p.frac = th(5); p.x1max = th(6); p.x0 = th(7:8).';
  y = cascaded_tanks_sim (u, Ts, p);
endfunction

function r = rms_ (e)
  r = sqrt (mean (e(:) .^ 2));
endfunction

## Every candidate of every pass: effect, group, variant, score, p,
## significant, validation RMSE, screened, seconds, reason.
function t = pass_tables (R)
  t = "";
  H = {};
  if (isfield (R, "history") && ! isempty (R.history))
    for i = 1:numel (R.history)
      if (isfield (R.history(i), "ranking"))
        H{end+1} = R.history(i).ranking;
      endif
    endfor
  endif
  if (isempty (H))
    H = {R.ranking};
  endif
  for i = 1:numel (H)
    rk = H{i};
    t = [t, sprintf("\nPass %d:\n\n", i)];
    t = [t, "| effect | group | variant | score | p | sig. | RMSE (V) | ", ...
         "screened | s | reason |\n", ...
         "|---|---|---|---|---|---|---|---|---|---|\n"];
    for j = 1:numel (rk)
      r = rk(j);
      t = [t, sprintf(["| %s | %s | %s | %.4f | %.3g | %d | %.4g | %d | ", ...
                       "%.1f | %s |\n"],
                      fld (r, "effect"), fld (r, "group"), fld (r, "variant"),
                      num (r, "score"), num (r, "p"), num (r, "significant"),
                      num (r, "rmse"), num (r, "screened"), num (r, "seconds"),
                      strrep (fld (r, "reason"), "|", "/"))];
    endfor
    ## each candidate's variants (BIC on the estimation record) and evidence
    t = [t, "\nVariants (BIC, estimation record) and evidence:\n\n"];
    for j = 1:numel (rk)
      r = rk(j);
      v = "";
      if (isfield (r, "variants") && isstruct (r.variants))
        for k = 1:numel (r.variants)
          v = [v, sprintf("%s: %.1f%s; ", r.variants(k).variant,
                          r.variants(k).bic,
                          ifelse_ (r.variants(k).converged, "",
                                   " (screened)"))];
        endfor
      endif
      ev = "";
      if (isfield (r, "evidence") && isstruct (r.evidence)
          && isfield (r.evidence, "text"))
        ev = strrep (r.evidence(1).text, "\n", " ");
      endif
      if (! isempty (v) || ! isempty (ev))
        t = [t, sprintf("- %s: %s%s\n", fld (r, "effect"), v, ev)];
      endif
    endfor
  endfor
endfunction

function s = ifelse_ (c, a, b)
  if (c)
    s = a;
  else
    s = b;
  endif
endfunction

function v = fld (r, f)
  v = "";
  if (isfield (r, f) && ischar (r.(f)))
    v = strrep (r.(f), "\n", " ");
  endif
endfunction

function v = num (r, f)
  v = NaN;
  if (isfield (r, f) && (isnumeric (r.(f)) || islogical (r.(f)))
      && isscalar (r.(f)))
    v = double (r.(f));
  endif
endfunction

function write_report (S, NN, file, rule, variant)
  fid = fopen (file, "w");
  if (fid < 0)
    error ("residtrace_cascaded_tanks:badInput",
           "residtrace_cascaded_tanks: cannot write %s", file);
  endif
  p = cascaded_tanks_sim ("params");
  if (strcmp (variant, "strong"))
    p.urms = 2.2;
  endif
  fprintf (fid, "# residtrace on simulated Cascaded Tanks records (%s)\n\n",
           variant);
  fprintf (fid, ["Records: devel/validation/cascaded_tanks_sim.m (k1 = %g, k2 = %g, ", ...
                 "k3 = %g, k4 = %g, frac = %g, rims %g V and %g V, x0 = ", ...
                 "[%g %g] V, sensor noise %g V rms, %g-V quantisation, ", ...
                 "multisine %g +- %g V rms up to %g Hz, %d samples at ", ...
                 "Ts = %g s). Linear model: srivc with the structure of ", ...
                 "rule '%s' (simplest: as residtrace_lab_rigs; best: the ", ...
                 "best ", ...
                 "validation R_T^2) among %d structures; then ", ...
                 "residtrace (de, M, \"validation\", dv) with defaults. ", ...
                 "Every RMSE is a validation simulation in V. Overflow: ", ...
                 "samples with the upper (u) / lower (l) tank at its rim, ", ...
                 "estimation / validation record.\n\n"],
           p.k1, p.k2, p.k3, p.k4, p.frac, p.x1max, p.x2max, p.x0(1),
           p.x0(2), p.sigma, p.q, p.umean, p.urms, p.fmax, p.N, p.Ts,
           rule, rows (NN));
  fprintf (fid, ["| draw | overflow u/l est, u/l val | structure | BLA ", ...
                 "from rest | BLA x0 est. | effects named (in order) | ", ...
                 "R.rmse_given | R.rmse_before | R.rmse_final | final / ", ...
                 "before | grey-box (right physics) | noise floor | ", ...
                 "time wall / CPU (s) |\n"]);
  fprintf (fid, "|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  for i = 1:numel (S)
    s = S(i);
    fprintf (fid, ["| %d | %d/%d, %d/%d | [%s] | %.3f | %.3f | %s | %.3f ", ...
                   "| %.3f | %.3f | %.2f | %.3f | %.3f | %.0f / %.0f |\n"],
             s.draw, s.overflow, num2str (s.nn), s.rmse_bla_rest,
             s.rmse_bla_x0, strjoin (s.all, ", "), s.rmse_given,
             s.rmse_before, s.rmse_final, s.rmse_final / s.rmse_before,
             s.rmse_grey, s.rmse_noise, s.seconds, s.cpu);
  endfor
  for i = 1:numel (S)
    s = S(i);
    fprintf (fid, "\n## Draw %d\n\n", s.draw);
    fprintf (fid, "Structures (srivcstruc, validation R_T^2):\n\n");
    fprintf (fid, "| RT2 | YIC | nn |\n|---|---|---|\n");
    for j = 1:rows (s.V)
      fprintf (fid, "| %.5f | %.3g | [%s] |\n", s.V(j,1), s.V(j,2),
               num2str (s.V(j,3:end-2)));
    endfor
    fprintf (fid, "\nsrivc [%s]: warning '%s'; %s\n", num2str (s.nn),
             s.srivc_warning, s.srivc_reason);
    fprintf (fid, "Offsets used for the BLA figures: input %g V, output %g V\n",
             s.offsets);
    if (! isempty (s.error))
      fprintf (fid, "\nresidtrace error: %s\n", s.error);
    endif
    fprintf (fid, "\nLevels: %s\n\nVerdict: %s\n", s.levels, s.verdict);
    fprintf (fid, "%s\n", s.passes);
    if (! isempty (s.grey))
      fprintf (fid, ["\nGrey-box: %d LM iterations; estimation RMSE ", ...
                     "%.4f V; ", ...
                     "theta [k1 k2 k3 k4 frac x1max x10 x20] = [%s], true ", ...
                     "[%s]\n"], s.grey.iterations, s.rmse_grey_est,
               num2str (s.grey.theta, 4), num2str (s.grey.true, 4));
    endif
    w = strtrim (s.log);
    if (! isempty (w))
      fprintf (fid, ["\nresidtrace's printed output and warnings:\n\n", ...
                     "```\n%s\n```\n"], w);
    endif
  endfor
  fclose (fid);
endfunction

## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{tpl} =} fuzz_public_templates ()
## Well-formed calls of every public function of @file{octave/*.m} for the
## public fuzz test (@file{test_fuzz_public.m}, @file{fuzz_public_child.m}):
## a struct with one field per function, each a cell of argument lists
## (cells), that the child mutates as it mutates its generic templates, so
## that the random calls also reach beyond each function's first argument
## check.  @file{test_fuzz_public.m} fails when a public function has no
## field here (the list is kept complete as the API grows) or when a field
## names no public function.  A method or constructor may have calls too,
## under @code{<class>_<name>} (its first argument is the object; for the
## pre-LTI forms of @code{step}, @code{bode}, @code{pzmap}: @code{double}).
##
## Among them, calls that once hung, failed without an identifier or
## returned garbage silently: NaN parameters (@code{setpvec}, @code{set}
## of theta; the model then hung the control package's routines), a
## cut-off far above the Nyquist frequency, an input that is zero at every
## sample, a constant output, missing samples in the data methods,
## integer-typed arguments.
## @end deftypefn

function tpl = fuzz_public_templates ()
  Ts = 0.1;
  n = 200;
  k = (1:n)';
  u = sign (sin (k * 0.37 + 0.3) + 0.4 * sin (k * 0.11));
  u(u == 0) = 1;
  y = filter ([0 0.05 0.04], [1 -1.6 0.7], u) + 0.01 * sin (k * 2.1);
  r = u;
  data = iddata (y, u, Ts);
  data2 = iddata ([y, filter([0 0.04], [1 -0.8], circshift (u, 17))],
                  [u, circshift(u, 17)], Ts);
  dcl = iddata (u, r, Ts);
  yn = y;
  yn(50:55) = NaN;                  # a gap of missing samples
  gap = iddata (yn, u, Ts);
  M = idtf (2, [1 3 2]);
  P = idpoly (1, 2, 1, 1, [1 3 2], "Ts", 0);
  C = struct ("num", [1 -0.5], "den", [1 -1]);
  thm = repmat ([3 2 2], n, 1);
  w = logspace (-1, 1, 20)';
  G = 2 ./ ((1i * w) .^ 2 + 3 * 1i * w + 2);
  frd = idfrd (G, w, "Ts", 0);
  hw = struct ("ltim", idtf (1, [1 1]), "NL_H", [1 0.5]);
  ## a longer record for the functions that split it into blocks
  kl = (1:800)';
  ul = sign (sin (kl * 0.37 + 0.3) + 0.4 * sin (kl * 0.11));
  ul(ul == 0) = 1;
  long = iddata (filter ([0 0.05 0.04], [1 -1.6 0.7], ul)
                 + 0.01 * sin (kl * 2.1), ul, Ts);
  ctl = {"controller", C, "r1", r, "r2", zeros(n, 1)};
  ## LPV basis functions of a scheduling signal (na = 2, nb = 1)
  pl = sin (k' * 0.05);
  depa = zeros (2, 2, n);
  depa(:,1,:) = [ones(1, n); pl];
  depa(:,2,:) = [ones(1, n); pl];
  depb = ones (1, 1, n);
  alpv = [1 0; 3 0.5; 2 0.3];
  ## a heated bar: 11 nodes, 60 instants, a source at the middle node
  hd2 = struct ("x", 0:0.1:1, "t", 0:59);
  hd1 = struct ("Input", zeros (60, 11));
  hd1.Input(mod (0:59, 20) < 10, 6) = 0.01;
  hd1.Output = zeros (60, 11);
  try
    hd1.Output = sim_heat ([1e-3 1], hd1, hd2, zeros (1, 11));
  catch
  end_try_catch
  hic = zeros (1, 11);
  ## a skewed input for the errors-in-variables estimators
  us = exp (sin (k * 0.37 + 0.3) + 0.4 * sin (k * 0.11));
  eiv = iddata (filter ([0 0.05 0.04], [1 -1.6 0.7], us), us, Ts);
  ## a typical record: PRBS into 4/(s^2+2.4s+4), 381 samples, Ts = 0.05
  Mp = idpoly (1, 4, 1, 1, [1 2.4 4], "Ts", 0);
  kp = (1:381)';
  up = sign (sin (kp * 0.61 + 0.2) + 0.5 * sin (kp * 0.23));
  up(up == 0) = 1;
  dp = iddata (simc (Mp, up, 0.05), up, 0.05, "InterSample", "zoh");
  ## the same output, an input zero at every sample
  dz = iddata (get (dp, "OutputData"), zeros (381, 1), 0.05);
  ## a constant output
  dc = iddata (2 * ones (381, 1), up, 0.05);
  yg = get (dp, "OutputData");
  yg(100:110) = NaN;                # 11 missing samples
  dg = iddata (yg, up, 0.05);
  far = {"lambda_svf", 1e9};        # far above pi/Ts = 62.8 rad/s

  tpl = struct ();
  tpl.Ham = {{u}, {}};
  tpl.Wie = {{u}, {}};
  tpl.arx = {{data, [2 2 1]}, {gap, [2 1 1]}};
  tpl.extractPoles = {{alpv, depa}};
  tpl.extractZeros = {{[1 2; 3 4], ones(2, 2, 5)}};
  tpl.bandwidthc = {{M}, {2, [1 3 2]}};
  tpl.bode4frozensys = {{thm, [2 1], "w", w}, {M, "w", [1 2]}};
  tpl.bodeoptions = {{}, {"cstprefs"}};
  tpl.bodeplot = {{M}, {M, "r", P}};
  tpl.chisqr = {{3, 100, 0.95}};
  tpl.cl2srivc = {{data, dcl, [1 2 0], [2 2 0]}};
  tpl.clrivc = {{data, dcl, [1 1 1 2 0], C}};
  tpl.clrivsvf = {[{data, [2 1 0], "lambda_svf", 3}, ctl]};
  tpl.clrsrivc = {[{data, [1 2 0], "lambda_svf", 3}, ctl]};
  tpl.clsrivc = {{data, dcl, [1 2 0], C}};
  tpl.comparec = {{data, M}, {data, thm, [2 1 0]}, {dc, Mp}};
  tpl.compress = {{[y u], Ts, 0.05}, {y, Ts, 0.05}};
  tpl.cra = {{data}, {data, 20, 5, 0}};
  tpl.dbode = {{0.1, [1 -0.9], Ts}, {0.1, [1 -0.9], Ts, w}};
  tpl.delayest = {{data}, {data, 2, 2, 0, 5}};
  tpl.freqs = {{2, [1 3 2], w}, {2, [1 3 2]}};
  tpl.hrivc = {{data, [1 1 1 2 0]}};
  tpl.hsrivc = {{data, [1 2 0]}, {gap, [1 2 0]}};
  tpl.hwsrivc = {{data, [1 3 0]}};
  tpl.idctm = {{2, [1 3 2]}, {2, [1 3 2], "nk", 1}};
  tpl.idinput = {{n}, {n, "prbs", [0 0.2]}};
  tpl.idplot = {{data}, {data, 1:50}};
  tpl.idresamp = {{data, 2}, {y, 0.5}};
  tpl.ivsvf = {{data, [2 1 0], 3}, {gap, [2 1 0], "lambda_svf", 3}};
  tpl.lssvf = {{data, [2 1 0], 3}, {y, u, Ts, [2 1 0], 3}};
  tpl.oe = {{data, [1 2 0]}, {gap, [2 2 1]}};
  tpl.oeOptions = {{}, {"Focus", "simulation"}};
  tpl.ord2 = {{2, 0.5}};
  tpl.phase = {{G}};
  tpl.prbs = {{7}, {7, 3}};
  tpl.present = {{M}, {P}};
  tpl.lpvrivc = {{data, [1 2 0 1], depa, depb}, ...
                 {y, u, Ts, [1 2 1 1], depa, depb, 1e-3, 5}};
  tpl.lpvsrivc = {{data, [1 2], depa, depb}, ...
                  {data, [1 2], depa, depb, 1e-4, 10, alpv, 0.05}};
  tpl.procsrivc = {{data, "P2U"}, {data, "P1D"}};
  tpl.sim_heat = {{[1e-3 1], hd1, hd2, hic}};
  tpl.local_filter3 = {{[1 0]' * [1 0], [1 -0.5]' * [1 -0.3], randn(20, 5)}};
  tpl.pdelssvf4heatdiffusion = {{hd1, hd2, struct("Str", "Euler", ...
                                                  "BF", [0.1 5])}};
  tpl.pdesrivc4heatdiffusion = {{hd1, hd2, hic}};
  tpl.pderivc4heatdiffusion = {{hd1, hd2, hic, [1 0 0 0]}};
  tpl.tocls = {{eiv, [2 1 0], 20, 3}, {eiv, [1 0 0], 10, "Tol", 1e-4}};
  tpl.tocils = {{eiv, [2 1 0], 20}, {eiv, [2 1 0], 20, 5, 3, 1e-4}};
  tpl.qnml = {{data, [2 1 0], "lambda_svf", 3}};
  tpl.rarx = {{data, [2 2 1], "ff", 0.98}, {[y u], [2 2 1], "kf", 1e-3}};
  tpl.rarxc = {{data, [2 1 1], "lambda_svf", 3}, ...
               {dz, [2 1 1], "lambda_svf", 3}};
  tpl.relay = {{1, [1 2 1], 0.05}, {1, [1 2 1], 0.05, "NumCycle", 3}};
  tpl.residc = {{data, M}, {data, thm, [2 1 0]}};
  ## residtrace on 320 samples (the fewest its validation third takes:
  ## about 10 s a call on this machine, 50 s on the 800 of long)
  mid = long(1:320);
  tpl.residtrace = {{mid, M}, {mid, idpoly([1 2.4 4], [], "Ts", 0)}};
  ## a complete result (residtrace runs once per child process)
  try
    R = residtrace (mid, idtf (0.9, [1 1.5 0.5]));
  catch
    R = struct ("steps", struct ("label", {"a"}, "params", {[]}));
  end_try_catch
  tpl.residtrace_table = {{R}};
  tpl.residtrace_sim = {{R, mid}, {R, mid, "model", "top"}};
  tpl.residtrace_plot = {{R, [tempname() ".png"]}};
  ## its model (an empty one when residtrace failed: every call an error)
  Mt = idtraced ();
  if (isfield (R, "final_model"))
    Mt = R.final_model;
  endif
  tpl.rivc = {{data, [1 1 1 2 0]}, {gap, [1 0 0 2 0]}};
  tpl.rivsvf = {{data, [2 1 0], "lambda_svf", 3}, {gap, [2 1 0], 3}, ...
                [{dp, [2 1 0]}, far, {"tsiv", 5}], ...
                {dz, [2 1 0], "lambda_svf", 3}};
  tpl.rlsconverge = {{long, [2 1 0], "lambda_svf", 3}, ...
                     {data, [2 1 0], "lambda_svf", 3, "nblocks", 3}, ...
                     {dz, [2 1 0], "lambda_svf", 3}};
  tpl.rlssvf = {{data, [2 1 0], "lambda_svf", 3}, {gap, [2 1 0], 3}, ...
                [{dp, [2 1 0]}, far], {dz, [2 1 0], "lambda_svf", 3}};
  tpl.rsrivc = {{data, [1 2 0], "lambda_svf", 3}, {gap, [1 2 0], 3}, ...
                [{dp, [1 2 0]}, far, {"tsiv", 5}], ...
                {dz, [1 2 0], "lambda_svf", 3}};
  tpl.selcstruc = {{[0.9 0.1 1 2 0 1 1; 0.8 0.2 1 1 0 2 1]}, ...
                   {[0.9 0.1 1 2 0 1 1; 0.8 0.2 1 1 0 2 1], "c2sort", "RT2"}};
  tpl.sidgpmf = {{data2, 3, 3, 3}, {data2, 3, 3, 3, 2, 10}};
  tpl.shadedplot = {{(1:n)' * Ts, y, y + 0.1}};
  tpl.simc = {{M, data}, {M, u, Ts}, {thm, [2 1 0], data}};
  tpl.simc_hw = {{hw, data}};
  tpl.sineresp = {{M, 1, (0:n-1)' * Ts}};
  tpl.spafdr = {{data}, {data, 20, w}};
  tpl.simulLPVCT = {{u, alpv, depa, 2, depb, Ts}};
  tpl.ssbcgpmf = {{data2, [1 1], [3; 3], -1}, ...
                  {data2, [1 1], [2; 4], [-0.5; -1], 10}};
  tpl.ssivgpmf = {{data2, [1 1], [3; 3]}, {data2, [1 1], [2; 4], 10}};
  tpl.sslsgpmf = {{data2, [1 1], [3; 3]}, {data, 2, 3}};
  tpl.srivc = {{data, [1 2 0]}, {gap, [1 2 0]}, ...
               {data, [1 2 0], "lambda", 3}, ...
               {data, idpoly(1, 4, 1, 1, [1 2 4], "Ts", 0)}};
  tpl.srivcstruc = {{data, data, [1 2 0; 2 2 0]}, ...
                    {data, [], [1 1 0; 2 2 0]}, ...
                    {data, data, [1 2 0], "NN", "list", ...
                     "InitialCondition", "e"}, ...
                    {data, [], [1 2 0], "Denominator", "Different"}};
  tpl.stepplot = {{M}, {M, "r", P}};
  tpl.svfcutoff = {{long, [1 2 0]}, {dp, [1 2 0], "segments", 1e308}};
  tpl.svfscaling = {{data, [2 1 0], "lambda_svf", 3}};
  tpl.tfcoe = {{data, 2, 1}, {data, 2, 0, 0.1}, ...
               {data, 2, 1, "TdMin", 0.05, "NumTd", 8, "StepReduction", 3}, ...
               {data, 2, 0, "Integration", "on", "FocusOrder", 3}};
  tpl.tfest = {{data, 2}, {data, 2, 1}, {frd, 2, 0}};
  tpl.tfestOptions = {{}, {"InitialCondition", "zero"}};
  tpl.tffcoe = {{frd, 2, 0}, {frd, M}};
  tpl.tffsrivc = {{frd, 2, 0}, {frd, M}};
  tpl.tfrivc = {{data, 2, 1}, {data, 2, 0, "NN", [1 1]}};
  tpl.tfsrivc = {{data, 2, 1}, {data, M}, ...
                 {data, 2, 1, "Focus", 5}, ...
                 {data, 2, 0, "Integration", "on"}};
  tpl.tfsrivc_init = {{data, 2, 1}};
  ts = throttlesim ("duration", 1, "noisevar", 0);
  tpl.throttleid = {{ts, "clrsrivc", "tsiv", 0.5}};
  tpl.throttleparams = {{}};
  tpl.throttlesim = {{}, {0.5 * ones(50, 1), 1e-3}};

  ## methods and constructors
  Pp = idproc ("P1D", "Kp", 2, "Tp1", 0.5, "Td", 0.1);
  tpl.idmodel_setpvec = {{Mp, [4; 2.4; NaN]}, {Mp, [4; 2.4; 4]}, ...
                         {M, [NaN 3 2 0]}, {Pp, [2 Inf 1]}};
  tpl.idmodel_set = {{Mp, "theta", [4 2.4 NaN]}, ...
                     {Mp, "covariance", -eye(3)}, {Pp, "Kp", Inf}};
  tpl.idmodel_setcov = {{Mp, int8(zeros (3))}, {Mp, eye(3)}};
  tpl.idmodel_idmodel = {{"idtf", struct(), -1, 1}, {"idtf", struct(), 1, NaN}};
  for f = {"damp", "pole", "zero", "ss", "pzmap", "zpplot", "d2c"}
    tpl.(["idmodel_" f{1}]) = {{Mp}};
  endfor
  tpl.iddata_nkshift = {{dp, int8(2)}, {dp, 2}};
  tpl.iddata_detrend = {{dg}, {dg, 1}};
  tpl.iddata_fft = {{dg}, {dp}};
  tpl.iddata_horzcat = {{dp, dp}, {dp, dz}};
  tpl.double_step = {{4, [1 2.4 4], {1}}, {4, [1 2.4 4]}};
  tpl.double_bode = {{4, [1 2.4 4], {1}}, {4, [1 2.4 4]}};
  tpl.double_pzmap = {{4, [1 2.4 4], {1}}, {4, [1 2.4 4]}};
  ul320 = get (mid, "InputData");
  tpl.idtraced_idtraced = {{get(Mt)}, {}};
  tpl.idtraced_sim = {{Mt, mid}, {Mt, ul320, Ts}};
  tpl.idtraced_get = {{Mt}, {Mt, "u0"}};
  tpl.idtraced_present = {{Mt}};
  tpl.idtraced_subsref = {{Mt, struct("type", ".", "subs", "linear")}};
  tpl.simc{end+1} = {Mt, ul320, Ts};
  tpl.comparec{end+1} = {mid, Mt};
endfunction

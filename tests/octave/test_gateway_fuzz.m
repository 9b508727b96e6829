## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## Calls the compiled gateways directly with arbitrary arguments: every call
## must either succeed or raise an error with an identifier
## <public name>:<reason>; none may crash Octave (a crash ends this process
## and so fails the test).  Each gateway takes its data arrays positionally
## and ONE options struct (mex/options_reader.hpp); besides replacing each
## positional argument, the test removes each field of the options (a
## required one must give <name>:badOption), adds an unknown field (must
## give <name>:badOption), replaces each field by every value of a pool of
## wrong types and sizes, and passes non-struct or non-scalar options.
## The environment variables CTID_FUZZ_SEED and CTID_FUZZ_CALLS change the
## seed and the number of random argument lists (see below).  Every gateway
## of mex/CMakeLists.txt's CTID_GATEWAYS must be built and have a valid
## call here, or the test fails (the list stays complete as gateways are
## added).
function test_gateway_fuzz ()
  root = ctid_test_root ();
  priv = fullfile (root, "octave", "private");
  tmp = tempname ();
  mkdir (tmp);
  cleanup = onCleanup (@() remove_dir (tmp));
  ## Every compiled gateway; each must have a valid call below (checked
  ## after the list of calls is built), so a new gateway cannot be missed.
  g = dir (fullfile (priv, "*.mex"));
  gateways = cellfun (@(f) f(1:end-4), {g.name}, "UniformOutput", false);
  for i = 1:numel (gateways)
    copyfile (fullfile (priv, [gateways{i} ".mex"]), tmp);
  endfor
  addpath (tmp);
  ## the calls run in a working directory of their own (removed with tmp),
  ## so that nothing they might write lands in the source tree
  here = pwd ();
  work = fullfile (tmp, "work");
  mkdir (work);
  cd (work);
  back = onCleanup (@() cd (here));

  ## CTID_FUZZ_SEED (default 42) seeds the data and the random argument
  ## lists, CTID_FUZZ_CALLS (default 300) is the number of random argument
  ## lists per gateway call form.
  seed = env_number ("CTID_FUZZ_SEED", 42);
  ntrials = env_number ("CTID_FUZZ_CALLS", 300);
  rand ("state", seed);
  randn ("state", seed);
  pool = value_pool ();
  y = randn (50, 1);
  u = randn (50, 1);
  ## A plant response for the offline (refined-IV) valid call: on y and u
  ## unrelated, its closed-loop instruments are rank deficient and the
  ## engine refuses the record (an identified error, not a valid call).
  yp = filter ([0 0.05], [1 -1.6 0.7], u);
  rls = struct ("intersample", "zoh", "na", 2, "nb", 1, "nk", 0,
                "lambda_svf", 2, "svf", "normalised", "adm", "kf",
                "adg", 1e-4 * eye (3), "th0", [], "P0", [], "form", "potter",
                "Gamma", [], "scaling", [1; 2; 3], "ic", false, "tsls", 0.5,
                "precision", "single");
  riv = struct ("intersample", "zoh", "na", 2, "nb", 1, "nk", 0,
                "lambda_svf", 2, "svf", "normalised", "adm", "kf",
                "adg", 1e-4 * eye (3), "th0", [], "P0", [],
                "method", "rsrivc", "tsiv", 1, "dtupdate", 0.1,
                "stability", "keep", "mtheta_num", [], "mtheta_den", [],
                "prefilter", "unit", "A", [], "controller_num", [1 -0.5],
                "controller_den", [1 -1], "r1", u, "r2", zeros (50, 1),
                "scaling", [1; 2; 3], "antiwindup", 300,
                "antiwindup_lambda", 0.998, "precision", "double");
  qn = rls;
  qn.adg = zeros (3);
  qn.form = "standard";
  qn.scaling = [];
  qn.tsls = 0;
  qn.precision = "double";
  qn.estimator = "rlssvf";
  qn.mode = "search";
  qn.q0 = [1e-4; 1e-4; 0];
  qn.lb = [1e-6; 1e-6; 0];
  qn.ub = [1e-2; 1e-2; 0];
  qn.free = [1; 1; 0];
  qn.maxeval = 4;
  qn.xtol = 1e-2;
  offline = struct ("intersample", "zoh", "na", 2, "nb", 1, "nk", 0,
                    "lambda_svf", 2, "svf", "normalised",
                    "method", "clsrivc", "tol", 1e-6, "maxiter", 5,
                    "theta_init", [], "controller_num", [1 -0.5],
                    "controller_den", [1 -1], "r1", u, "r2", zeros (50, 1));
  ## Box-Jenkins refined IV (rivc_mex): 200 samples (the ARMA model needs
  ## more than 50).
  ub = randn (200, 1);
  yb = filter ([0 0.05], [1 -1.6 0.7], ub) + 0.01 * randn (200, 1);
  bj = struct ("method", "rivc", "nb", 1, "nc", 1, "nd", 1, "nf", 2,
               "nk", 0, "delay", 0, "intersample", 0, "tol", 1e-6,
               "maxiter", 5, "theta_init", [], "cutoffs", [],
               "max_starts", 3, "arma_maxiter", 10, "controller_num", [],
               "controller_den", [], "cl_nb", 1, "cl_nf", 1, "cl_nk", 0);
  pem = struct ("model", "oe_ct", "nf", 2, "nb", 1, "nk", 0, "delay", 0.05,
                "estimate_delay", true, "delay_max", 1, "cutoff", 0,
                "intersample", "zoh", "theta_init", [], "maxiter", 5, "tol", 1e-8);
  pemarx = struct ("model", "arx", "na", 2, "nb", 1, "nk", 1);
  sim = struct ("intersample", "zoh", "na", 2, "nb", 1, "nk", 0,
                "substeps", 1, "x0", [], "noise", []);
  ## residtrace's effect model: input, Coulomb and y^3 channels, closed
  ## loop, per-sample coefficients
  eff = struct ("ts", 0.1, "f", [1.2 4], "b", [0 0.5 0; 4 -1 0.1],
                "kind", [4 1 3], "nk", [1 0 0], "param", [0 0 3],
                "y_off", 0.1, "substeps", 2, "controller_num", [1 -0.5],
                "controller_den", [1 -1], "r1", u, "r2", zeros (50, 1),
                "s", zeros (50, 1), "poly", [0 0.1],
                "f_t", repmat ([1.2 4], 50, 1),
                "b_t", repmat ([0 4 0.5 -1 0 0.1], 50, 1));
  ## residtrace's physical realisations: a two-tank cascade, simulated and
  ## fitted
  phys = struct ("kind", "cascade", "ts", 2, "g", "sqrt", "b", 0.0012,
                 "d", 0, "alpha", 0.01, "gamma", 0.085, "c", 0, "hi", 0.4,
                 "substeps", 4);
  physfit = setfield (setfield (phys, "maxiter", 2), "h0", 0.1);
  ## a residtrace model (mex/residtrace_model_io.hpp), simulated, scored on
  ## a record and fitted
  rch = struct ("name", "u1", "type", "input", "col", 1, "param", [],
                "nb", 1, "nk", 0, "B", 0.5);
  rtm = struct ("F", [1 1.2], "fixed", false, "channels", rch,
                "out", struct ("type", "offset", "c", 0.1, "cstd", NaN,
                               "omega", 0),
                "intersample", "zoh", "levels", false, "x0", true,
                "noise", [], "ltv", [], "phys", []);
  rtV = struct ("y", y, "u", u, "Ts", 0.1, "loop", [], "pre", [],
                "missing", false (50, 1));
  rtD = setfield (rtV, "ysm", y);
  rsim = struct ("ts", 0.1, "substeps", 2, "loop", [], "thm", []);
  rval = struct ("substeps", 2, "thm", [], "yh", []);
  rfit = struct ("starts", {{[]}}, "maxiter", 3, "keep_order", false,
                 "substeps", 2);
  ## its candidates and the choice among variants
  rcand = rmfield (rfit, "starts");
  rsel = setfield (rcand, "starts", {{[]}, {rtm.F}});
  ## the current model with its estimation residual, not at rest
  rtme = setfield (setfield (rtm, "e_est", y), "x0", false);
  rphys = struct ("ts", 0.1);
  rvel = struct ("ts", 0.1, "lambda", 5, "output_itself", false);
  rcas = struct ("kind", "cascade", "g", "sqrt", "gamma", 0.085,
                 "alpha", 0.01, "d", 0, "c", 0, "hi", 0.4, "h0", 0.1);
  ## Calls: {gateway, positional arguments with the options struct last,
  ## required fields}.
  calls = {
    {"rlssvf_mex", {"rlssvf", y, u, 0.1, rls}, ...
     {"na", "nb", "nk", "lambda_svf"}}
    {"simc_mex", {"simc", u, 0.1, [2 4 4], sim}, {"na", "nb", "nk"}}
    {"pem_mex", {"tfcoe", yp, u, 0.1, pem}, {"model", "nf", "nb"}}
    {"pem_mex", {"arx", yp, u, 1, pemarx}, {"model", "na", "nb", "nk"}}
    {"effect_sim_mex", {"residtrace", [u, u, u], eff}, ...
     {"ts", "f", "b", "kind", "nk", "param"}}
    {"effect_sim_mex", {"residtrace", "physsim", abs(u), phys}, ...
     {"kind", "ts", "b", "d", "alpha", "gamma", "c"}}
    {"effect_sim_mex", {"residtrace", "physfit", abs(u), y, physfit}, ...
     {"kind", "ts", "b", "d", "alpha", "gamma", "c", "maxiter"}}
    {"effect_sim_mex", {"residtrace", "simulate", rtm, u, rsim}, {"ts"}}
    {"effect_sim_mex", {"residtrace", "valerror", rtm, rtV, rval}, {}}
    {"effect_sim_mex", {"residtrace", "fitmodel", rtm, rtD, rfit}, ...
     {"maxiter"}}
    {"effect_sim_mex", {"residtrace", "candidate", "offset", rtm, rtD, ...
                        rcand}, {"maxiter"}}
    {"effect_sim_mex", {"residtrace", "candidate", "viscous", ...
                        setfield(rtm, "fixed", true), rtD, rcand}, ...
     {"maxiter"}}
    {"effect_sim_mex", {"residtrace", "candidate", "sinusoid", rtme, rtD, ...
                        setfield(rcand, "validation_samples", 50)}, ...
     {"maxiter"}}
    {"effect_sim_mex", {"residtrace", "candidate", "delay", rtme, rtD, ...
                        setfield(setfield(rcand, "maxdelay", 2), ...
                                 "maxlag", 5)}, {"maxiter"}}
    {"effect_sim_mex", {"residtrace", "candidate", "initial_state", rtme, ...
                        rtD, rcand}, {"maxiter"}}
    {"effect_sim_mex", {"residtrace", "candidate", "colored_noise", rtme, ...
                        rtD, rcand}, {"maxiter"}}
    {"effect_sim_mex", {"residtrace", "candidate", "state_nonlinearity", ...
                        setfield(rtm, "np", 3), rtD, rcand}, {"maxiter"}}
    {"effect_sim_mex", {"residtrace", "candidate", "static_nonlinearity", ...
                        setfield(rtm, "np", 3), rtD, rcand}, {"maxiter"}}
    {"effect_sim_mex", {"residtrace", "candidate", "saturation", ...
                        setfield(setfield(rtm, "e_est", y - 0.5 * u), ...
                                 "np", 1), rtD, rcand}, {"maxiter"}}
    {"effect_sim_mex", {"residtrace", "driftsegments", ...
                        setfield(setfield(setfield(rtm, "theta", [1.2 0.5]), ...
                                          "cov", eye(2)), "s2", 0.1), ...
                        rtD, setfield(rcand, "alpha", 0.01)}, ...
     {"maxiter", "alpha"}}
    {"effect_sim_mex", {"residtrace", "select", {rtm, rtm}, {"a", "b"}, ...
                        rtD, rsel}, {"maxiter", "starts"}}
    {"effect_sim_mex", {"residtrace", "physcascade", rtm, rtD, ...
                        struct("g", "sqrt", "clip", true)}, {}}
    {"effect_sim_mex", {"residtrace", "physmodelfit", ...
                        setfield(rtm, "phys", rcas), rtD, ...
                        struct("maxiter", 2)}, {"maxiter"}}
    {"effect_sim_mex", {"residtrace", "physical", rtm, rphys}, {"ts"}}
    {"effect_sim_mex", {"residtrace", "filter", y, [1 2], ...
                        struct("ts", 0.1, "rule", "zoh")}, {"ts", "rule"}}
    {"effect_sim_mex", {"residtrace", "free", 50, [1 2], ...
                        struct("ts", 0.1)}, {"ts"}}
    {"effect_sim_mex", {"residtrace", "dmtest", y, u, struct()}, {}}
    {"effect_sim_mex", {"residtrace", "whiteness", y, u, ...
                        struct("maxlag", 5)}, {"maxlag"}}
    {"effect_sim_mex", {"residtrace", "ar", y, struct("pmax", 3)}, ...
     {"pmax"}}
    {"effect_sim_mex", {"residtrace", "velocity", y, rvel}, {"ts", "lambda"}}
    {"effect_sim_mex", {"residtrace", "cascadelevels", rcas, struct()}, {}}
    {"riv_mex", {"clrsrivc", y, u, 0.1, riv}, ...
     {"na", "nb", "nk", "lambda_svf"}}
    {"qnml_mex", {"qnml", y, u, 0.1, qn}, ...
     {"na", "nb", "nk", "lambda_svf", "estimator", "mode", "q0", ...
      "lb", "ub", "free", "maxeval", "xtol"}}
    {"rivc_mex", {"rivc", yb, ub, 0.1, [], bj}, {}}
    {"offline_mex", {"clsrivc", yp, u, 0.1, offline}, ...
     {"na", "nb", "nk", "lambda_svf", "method", "controller_num", ...
      "controller_den", "r1", "r2"}}
  };
  ## The throttle gateway, in both modes (the Table 4.3 parameters, a short
  ## record near the limp-home position).
  addpath (fullfile (root, "octave"));
  plant = throttleparams ();
  phi_d = 0.5 * ones (50, 1);
  loop = struct ("plant", plant, "pid_num", [3 -2], "pid_den", [1 -1],
                 "filter_num", [0.009901 0.009901],
                 "filter_den", [1 -0.9802], "umax", 12, "substeps", 2,
                 "phi0", [], "Ts", 1e-3);
  tsim = loop;
  tsim.noise = zeros (50, 1);
  out = cell (1, 7);
  [out{:}] = throttle_mex ("throttlesim", phi_d, 1.4 * ones (50, 1), tsim);
  tid = loop;
  tid.method = "clrsrivc";
  tid.lambda_svf = 62;
  tid.adg = diag ([1e-6 5e-5]);
  tid.th0 = [];
  tid.P0 = [];
  tid.tsiv = 0.01;
  tid.phirule = "zoh";
  loop_required = {"Ts", "plant", "pid_num", "pid_den", "filter_num", ...
                   "filter_den", "umax"};
  calls(end+1:end+2) = {
    {"throttle_mex", {"throttlesim", phi_d, 1.4 * ones(50, 1), tsim}, ...
     loop_required}
    {"throttle_mex", {"throttleid", phi_d, out{1}, out{2}, out{4}, tid}, ...
     [loop_required, {"method", "lambda_svf", "adg"}]}
  };

  ## The block-oriented (Hammerstein) and frequency-domain gateways.
  yh = filter ([0 0.05], [1 -1.6 0.7], u + 0.5 * u .^ 2);
  hopts = struct ("model", "hsrivc", "nb", 1, "nf", 2, "nk", 0, "nc", 0,
                  "nd", 0, "nw", 1, "intersample", 0, "y_intersample", 1,
                  "tol", 1e-6, "maxiter", 3, "cutoffs", []);
  wf = logspace (-1, 1, 20)';
  Gf = 4 ./ ((1i * wf) .^ 2 + 2 * 1i * wf + 4) .* exp (-0.2i * wf);
  fopts = struct ("na", 2, "nb", 1, "tol", 1e-8, "maxiter", 20,
                  "delay", 0, "estimate_delay", true, "td_min", 0,
                  "td_max", 1, "num_td", 5, "grid", true,
                  "output_error", true, "theta_init", []);
  calls(end+1:end+2) = {
    {"hammerstein_mex", {"hsrivc", yh, [u u.^2], 0.1, hopts}, {"nb", "nf"}}
    {"freq_srivc_mex", {"tffcoe", wf, Gf, [], fopts}, {"na", "nb"}}
  };

  ## The identifiers of errors must name a public function of the toolbox.
  public_id ("", root);

  ## The offline refined-IV engine and the recursive DT ARX estimator.
  ropts = struct ("method", "srivc", "nf", 2, "group", 1, "nb", 1, "nk", 0,
                  "intersample", 0, "delay", 0, "tol", 1e-6, "maxiter", 5,
                  "max_starts", 2, "cutoffs", [], "theta_init", []);
  xopts = struct ("na", 2, "nb", 1, "nk", 1, "Ts", 0.1, "adm", "ff",
                  "adg", 0.99, "th0", [], "P0", [], "lambda", 0,
                  "continuous", true);
  calls(end+1:end+2) = {
    {"refined_iv_mex", {"srivc", yp, u, 0.1, [], ropts}, ...
     {"nf", "group", "nb", "nk"}}
    {"rarx_mex", {"rarx", yp, u, xopts}, {"na", "nb", "nk", "Ts"}}
  };

  ## The LPV simulator and refined IV (lpv_mex): y' + (2 + 0.5 p) y =
  ## (1 + 0.3 p) u with p a sine, 200 samples, estimated from its own
  ## noise-free output.
  pl = sin (0.05 * (1:200));
  dep = [ones(1, 200); pl];
  ul = randn (200, 1);
  lsim = struct ("Ts", 0.1, "A", [1 0; 2 0.5], "B", [1 0.3],
                 "dims_a", [2 1 200], "dims_b", [2 1 200]);
  yl = lpv_mex ("simulLPVCT", ul, dep, dep, lsim);
  yln = yl + 0.01 * randn (200, 1);
  lest = struct ("Ts", 0.1, "dims_a", [2 1 200], "dims_b", [2 1 200],
                 "nc", 0, "nd", 1, "tol", 1e-4, "maxiter", 5, "Ainit", [],
                 "Binit", []);
  calls(end+1:end+3) = {
    {"lpv_mex", {"simulLPVCT", ul, dep, dep, lsim}, ...
     {"Ts", "A", "B", "dims_a", "dims_b"}}
    {"lpv_mex", {"lpvsrivc", yl, ul, dep, dep, lest}, ...
     {"Ts", "dims_a", "dims_b"}}
    {"lpv_mex", {"lpvrivc", yln, ul, dep, dep, lest}, ...
     {"Ts", "dims_a", "dims_b"}}
  };

  ## The heat equation (pde_mex): a 1 m bar on 11 nodes, 40 instants, a
  ## source at the middle node, estimated from its own noise-free field.
  th = struct ("t", 0:39, "x", 0:0.1:1);
  uh = zeros (40, 11);
  uh(:, 6) = 0.01 * (mod (0:39, 10) < 5);
  hsim = struct ("theta", [1e-3 1], "t", th.t, "x", th.x, "ic", zeros (1, 11));
  yh = pde_mex ("sim_heat", uh, hsim);
  hls = struct ("t", th.t, "x", th.x, "rule", "euler", "lambda", [0.1 5]);
  hiv = struct ("t", th.t, "x", th.x, "ic", zeros (1, 11), "tol", 1e-6,
                "maxiter", 5);
  hriv = hiv;
  hriv.nn = [1 0 0 0];
  calls(end+1:end+5) = {
    {"pde_mex", {"sim_heat", uh, hsim}, {"theta", "t", "x", "ic"}}
    {"pde_mex", {"local_filter3", uh, struct("num", [1 2], "den", [1; -0.5])}, ...
     {"num", "den"}}
    {"pde_mex", {"pdelssvf4heatdiffusion", yh, uh, hls}, {"t", "x", "lambda"}}
    {"pde_mex", {"pdesrivc4heatdiffusion", yh, uh, hiv}, {"t", "x", "ic"}}
    {"pde_mex", {"pderivc4heatdiffusion", yh, uh, hriv}, {"t", "x", "ic", "nn"}}
  };

  ## The GPMF state-space gateway (gpmf_mex): 2 outputs, 2 inputs, 300
  ## samples of a stable system.
  kg = (1:300)';
  ug = [sign(sin(0.37 * kg) + 0.1), sign(cos(0.23 * kg) + 0.1)];
  yg = [filter([0 0.05], [1 -0.9], ug(:,1) + 0.5 * ug(:,2)), ...
        filter([0 0.04], [1 -0.8], ug(:,2))];
  gls = struct ("method", "ls", "nni", [1 1], "lambda", [3; 3], "n0", 1,
                "intersample", "zoh");
  giv = setfield (gls, "method", "iv");
  gbc = setfield (setfield (gls, "method", "bc"), "root", [-1; -1]);
  gsid = struct ("method", "sid", "i", 3, "j", 3, "lambda", 3, "n", 2);
  calls(end+1:end+4) = {
    {"gpmf_mex", {"sslsgpmf", yg, ug, 0.1, gls}, {"method", "nni", "lambda"}}
    {"gpmf_mex", {"ssivgpmf", yg, ug, 0.1, giv}, {"method", "nni", "lambda"}}
    {"gpmf_mex", {"ssbcgpmf", yg, ug, 0.1, gbc}, ...
     {"method", "nni", "lambda", "root"}}
    {"gpmf_mex", {"sidgpmf", yg, ug, 0.1, gsid}, ...
     {"method", "i", "j", "lambda"}}
  };

  ## The gateways' methods (a name as second argument): the exact
  ## state-space simulator (a fractional delay), the inverse of a Wiener
  ## block's polynomial, the Focus prefilter, the convergence detector
  ## of an RLSSVF start-up and the options of tfsrivc checked and filled in.
  ssopt = struct ("a", [-1 2; -2 -1], "b", [0; 1], "c", [1 0], "d", 0.5,
                  "nk", 0.5, "intersample", "foh");
  cdet = struct ("blocklength", 0.4, "nblocks", 10, "use_P", false);
  calls(end+1:end+6) = {
    {"simc_mex", {"simc", "state_space", u, 0.1, ssopt}, ...
     {"a", "b", "c", "d"}}
    {"hammerstein_mex", {"Wie", "poly_inverse", u, ...
                         struct("beta", [1 1.5 1])}, {"beta"}}
    {"refined_iv_mex", {"tfsrivc", "focus_filter", y, u, ...
                        struct("ts", 0.1, "band", [0.5 5], "order", 2)}, ...
     {"ts", "band", "order"}}
    {"rlssvf_mex", {"rlssvf", "converge", y, u, 0.1, rls, cdet}, ...
     {"blocklength"}}
    {"refined_iv_mex", {"tfsrivc", "tf_options", ...
                        struct("tdmax", 1, "numtd", 10, "stepmax", 0.1)}, ...
     {}}
    {"refined_iv_mex", {"tfsrivc", "delay_range", y, u, 0.1, ...
                        struct("tdmin", 0, "numtd", 10, "tdmax", 1, ...
                               "stepmax", 0.1, "td0", 0.2)}, ...
     {"tdmin", "numtd"}}
  };

  ## The output error from several starts (the delay bounded below), the
  ## reduction of an over-parametrised model (tfcoe's OverPar start) and
  ## the frequency data of a relay-feedback limit cycle.
  pems = struct ("model", "oe_ct", "nf", 2, "nb", 1, "estimate_delay", true,
                 "delay_max", 1, "starts", [1.6 0.7 0.05 0.1; 1 1 0.1 0.3].',
                 "delay_min", 0.05, "default_start", false,
                 "integrate", false, "maxiter", 3);
  red = struct ("nf", 2, "nb", 1, "band", [0.05 20], "td", 0.3,
                "search_delay", true, "delay_max", 1);
  ur = sign (sin (2 * pi * (0:59)' / 12) + 0.1);
  yr = filter ([0 0.2], [1 -0.8], ur);
  calls(end+1:end+3) = {
    {"pem_mex", {"tfcoe", yp, u, 0.1, pems}, {"model", "nf", "nb"}}
    {"pem_mex", {"tfcoe", "reduce", [4.2 4.6 3], [2 6], red}, ...
     {"nf", "nb", "band"}}
    {"freq_srivc_mex", {"tffsrivc", "relay", yr, ur, ...
                        struct("Ts", 0.1, "intsamp", true)}, {"Ts"}}
  };

  covered = cellfun (@(c) c{1}, calls, "UniformOutput", false);
  missing = setdiff (gateways, covered);
  if (! isempty (missing))
    error ("test_gateway_fuzz: no valid call for the gateway(s) %s",
           strjoin (missing, ", "));
  endif
  ## The truth is mex/CMakeLists.txt's CTID_GATEWAYS: every gateway listed
  ## there must be built (a gateway not compiled would escape the test) and
  ## have a valid call above.
  listed = cmake_gateways (root);
  unbuilt = setdiff (listed, gateways);
  if (! isempty (unbuilt))
    error ("test_gateway_fuzz: gateway(s) of CTID_GATEWAYS not built: %s",
           strjoin (unbuilt, ", "));
  endif
  missing = setdiff (listed, covered);
  if (! isempty (missing))
    error ("test_gateway_fuzz: no valid call for the gateway(s) %s",
           strjoin (missing, ", "));
  endif
  ncalls = 0;
  for c = 1:numel (calls)
    [name, base, required] = calls{c}{:};
    fname = base{1};
    ## The valid call works.
    feval (name, base{:});
    ## Each positional argument (the options too) replaced by every pool
    ## value, one at a time.
    for k = 1:numel (base)
      for p = 1:numel (pool)
        args = base;
        args{k} = pool{p};
        ncalls += check_call (name, args, nargout_for (p));
      endfor
    endfor
    ## The options struct, field by field.
    ncalls += fuzz_options (name, base, required, pool, "");
    if (isfield (base{end}, "plant"))    # the nested plant struct
      ncalls += fuzz_plant (name, base, pool);
    endif
    ## Non-scalar options: a struct array, a struct in a cell.
    args = base;
    args{end} = [base{end}, base{end}];
    ncalls += expect_id (name, args, [fname ":badInput"]);
    args{end} = {base{end}};
    ncalls += expect_id (name, args, [fname ":badInput"]);
    ## Too few and too many arguments.
    ncalls += expect_id (name, base(1:end-1), [fname ":badInput"]);
    ncalls += expect_id (name, [base, {base{end}}], [fname ":badInput"]);
    ## Random argument lists of random length.
    for trial = 1:ntrials
      n = randi ([0 8]);
      args = pool(randi (numel (pool), 1, n));
      if (n > 0 && rand () < 0.7)
        args{1} = fname;
      endif
      if (n > 1 && rand () < 0.5)
        args{end} = base{end};
      endif
      ncalls += check_call (name, args, randi ([0 4]));
    endfor
  endfor
  printf (["test_gateway_fuzz: %d calls (seed %d), all succeeded or ", ...
           "raised identified errors\n"], ncalls, seed);
endfunction

## The gateways named in mex/CMakeLists.txt's set(CTID_GATEWAYS ...).
function names = cmake_gateways (root)
  txt = fileread (fullfile (root, "mex", "CMakeLists.txt"));
  tok = regexp (txt, 'set\(CTID_GATEWAYS\s+([^)]*)\)', "tokens", "once");
  if (isempty (tok))
    error ("test_gateway_fuzz: no set(CTID_GATEWAYS ...) in %s",
           "mex/CMakeLists.txt");
  endif
  names = regexp (tok{1}, '\w+', "match");
  if (isempty (names))
    error ("test_gateway_fuzz: CTID_GATEWAYS lists no gateway");
  endif
endfunction

function v = env_number (name, def)
  v = str2double (getenv (name));
  if (isnan (v))
    v = def;
  endif
endfunction

## Removes each field (a required one must give fname:badOption), adds an
## unknown one (fname:badOption), replaces each by every pool value.
function n = fuzz_options (name, base, required, pool, prefix)
  n = 0;
  fname = base{1};
  opts = base{end};
  fields = fieldnames (opts);
  for f = 1:numel (fields)
    args = base;
    args{end} = rmfield (opts, fields{f});
    if (any (strcmp (fields{f}, required)))
      n += expect_id (name, args, [fname ":badOption"], fields{f});
    else
      n += check_call (name, args, 1);
    endif
    for p = 1:numel (pool)
      args = base;
      args{end}.(fields{f}) = pool{p};
      n += check_call (name, args, nargout_for (p));
    endfor
  endfor
  for unknown = {"bogus", "Lambda_svf", "lambda_SVF"}
    args = base;
    args{end}.(unknown{1}) = 1;
    n += expect_id (name, args, [fname ":badOption"], unknown{1});
  endfor
endfunction

## The same for the fields of options.plant (throttle_mex).
function n = fuzz_plant (name, base, pool)
  n = 0;
  fname = base{1};
  plant = base{end}.plant;
  fields = fieldnames (plant);
  for f = 1:numel (fields)
    args = base;
    args{end}.plant = rmfield (plant, fields{f});
    n += expect_id (name, args, [fname ":badOption"], ["plant." fields{f}]);
    for p = 1:numel (pool)
      args = base;
      args{end}.plant.(fields{f}) = pool{p};
      n += check_call (name, args, 1);
    endfor
  endfor
  args = base;
  args{end}.plant.bogus = 1;
  n += expect_id (name, args, [fname ":badOption"], "plant.bogus");
  for p = 1:numel (pool)
    args = base;
    args{end}.plant = pool{p};
    n += check_call (name, args, 1);
  endfor
endfunction

function remove_dir (d)
  confirm_recursive_rmdir (false, "local");
  rmpath (d);
  rmdir (d, "s");
endfunction

function n = nargout_for (p)
  n = mod (p, 4);
endfunction

## The call must fail with exactly this identifier (and its message must
## name the field, when given).
function n = expect_id (name, args, id, field)
  n = 1;
  try
    feval (name, args{:});
  catch err
    if (! strcmp (err.identifier, id))
      error ("test_gateway_fuzz: %s: expected '%s', got '%s': %s", name, id,
             err.identifier, err.message);
    endif
    if (nargin > 3 && isempty (strfind (err.message, ["'" field "'"])))
      error ("test_gateway_fuzz: %s: the message does not name '%s': %s",
             name, field, err.message);
    endif
    return;
  end_try_catch
  error ("test_gateway_fuzz: %s: expected the error '%s', the call succeeded",
         name, id);
endfunction

## True when the identifier ID is <public function>:<reason>; called once
## with ROOT to learn the public functions (octave/*.m).
function tf = public_id (id, root)
  persistent names = {};
  if (nargin > 1)
    f = dir (fullfile (root, "octave", "*.m"));
    names = cellfun (@(n) n(1:end-2), {f.name}, "UniformOutput", false);
    tf = true;
    return;
  endif
  tok = regexp (id, '^(\w+):\w+$', "tokens", "once");
  tf = ! isempty (tok) && any (strcmp (tok{1}, names));
endfunction

function n = check_call (name, args, nout)
  n = 1;
  try
    outs = cell (1, nout);
    [outs{:}] = feval (name, args{:});
  catch err
    if (isempty (err.identifier))
      error ("test_gateway_fuzz: %s raised an error without identifier: %s",
             name, err.message);
    endif
    if (! public_id (err.identifier))
      ## Octave's own argument errors (e.g. too many outputs) are fine only
      ## when they carry an identifier; ours must use the public name.
      if (! strncmp (err.identifier, "Octave:", 7))
        error ("test_gateway_fuzz: %s raised unexpected id '%s': %s",
               name, err.identifier, err.message);
      endif
    endif
  end_try_catch
endfunction

function pool = value_pool ()
  pool = {[], 0, -1, 1, 2, 3, 0.5, 1e300, -1e300, NaN, Inf, -Inf, 1i, ...
          [1 2], [1; 2], eye(3), -eye(3), ones(3, 2), zeros(3), ...
          randn(50, 1), randn(50, 2), randn(49, 1), randn(1, 50), ...
          (0:49)' * 0.1, flipud((0:49)' * 0.1), ones(50, 1), ...
          "zoh", "foh", "kf", "ff", "normalised", "ordinary", "rlssvf", ...
          "simc", "", "x", repmat("a", 1, 300), ["ab"; "cd"], {}, {1}, ...
          struct(), struct("a", 1), struct("na", {1, 2}), int8(3), ...
          uint16([1 2]), single(2), true, [true false], sparse(eye(3)), ...
          ones(2, 2, 2), @sin, zeros(0, 3), zeros(3, 0), [2 2 2], [1 4 0], ...
          [-1 1 0], [2.5 1]};
endfunction

## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn  {} {@var{V} =} srivcstruc (@var{ZE}, @var{ZV}, @var{NN})
## @deftypefnx {} {@var{V} =} srivcstruc (@var{ZE}, @var{ZV}, @var{NN}, @var{name}, @var{value}, @dots{})
## @deftypefnx {} {[@var{V}, @var{info}] =} srivcstruc (@dots{})
## Fit SRIVC models (@code{srivc}, thesis eqs. 2.8-2.13) of several
## structures and tabulate their quality, for @code{selcstruc} to pick one
## (CONTSID's structure selection).
##
## @var{ZE}: estimation data (@code{iddata}); @var{ZV}: validation data of
## the same inputs, or [] to judge on @var{ZE}. @var{NN}: the structures,
## one row [nb nf nk] each, as @code{srivc} reads them: with m inputs
## [nb_1..nb_m nf nk_1..nk_m] (2m + 1 columns: one common denominator) or
## [nb_1..nb_m nf_1..nf_m nk_1..nk_m] (3m columns: one denominator per
## input, CONTSID 7.3's 'Different' denominators); a two-row @var{NN} is
## read as the range [min; max] and expanded to every structure in it
## with nf >= 1, nb <= nf + 1 per input and at least one numerator
## parameter (unless the option @code{"NN", "list"} says the rows are
## structures).
##
## Options: @code{lambda} (the SVF cut-off of the start, default
## srivc's automatic start), @code{n0e} and @code{n0v} (first sample
## of ZE and ZV used to compute the criteria, default 1: the transient at
## the start can be left out), @code{NN} (@qcode{"auto"}, @qcode{"range"}
## or @qcode{"list"}), @code{Denominator} (@qcode{"Common"} or
## @qcode{"Different"}, CONTSID's option: checked against the number of
## columns of @var{NN}, which decides without it), @code{InitialCondition}
## (@qcode{"z"}, the default as CONTSID: the criteria simulate each model
## from rest; @qcode{"e"}, as MATLAB's @code{compare}: each model's
## initial state is estimated on the data it is judged on, ZV or ZE, by
## least squares on its free responses as @code{comparec (...,
## "InitialCondition", "e")}, so that a record that does not start at
## rest does not rank the structures by their transient from rest), and
## any @code{srivc} option
## (e.g. @code{Tol}, @code{MaxIter}, @code{InitialState}, which concerns
## the estimation).
##
## @var{V}: one row per structure, [RT2 YIC NN log(cond) N]: RT2 = 1 -
## var(y - y_sim)/var(y) on ZV (on ZE without ZV), YIC the Young
## information criterion on ZE, the structure, log10 of the condition
## number of the instrument-regressor matrix, and the number of samples
## used. A structure whose fit failed has RT2 = YIC = NaN. @var{info}:
## per structure @code{models} (cell), @code{status} (cell: each fit's
## status record as @code{srivc} reports it in @var{info}.status and
## @code{M.Report.Termination}: @code{converged}, @code{determined},
## @code{stable}, @code{reason}, @code{text}), its flags
## @code{converged}, @code{stable} and @code{determined} (false: srivc
## found the structure over-parameterised), @code{fit} (validation fit in
## per cent, 100 (1 - |y - y_sim| /
## |y - mean y|)), @code{x0} (cell: the initial state estimated with
## @code{"InitialCondition", "e"}, as @code{comparec}'s
## @code{estInfo.x0}; empty without it, and for a model whose state
## cannot be estimated, an unstable one, which is then judged from
## rest). y_sim is the model as estimated: with the output and input
## offsets that @code{srivc} estimated on a raw record (in the model's
## @code{Report.DataUsed.OutputOffset} and @code{InputOffset}), plus its
## free response from the estimated initial state with
## @code{"InitialCondition", "e"}.
##
## Missing samples (NaN in y or u) of ZE are bridged by @code{srivc}; its
## criteria then use the present samples (N counts them).  ZV is
## simulated sample by sample, so a NaN in ZV is an error
## (@code{srivcstruc:badInput}).
##
## @strong{Example}
## @example
## u = prbs (10, 8); Ts = 0.05; N = numel (u);
## y = simc (idctm (4, [1 2.4 4]), u, Ts) + 0.1 * randn (N, 1);
## ZE = iddata (y(1:end/2), u(1:end/2), Ts);
## ZV = iddata (y(end/2+1:end), u(end/2+1:end), Ts);
## V = srivcstruc (ZE, ZV, [1 1 0; 3 3 0]);
## selcstruc (V)
## @end example
## @seealso{selcstruc, srivc}
## @end deftypefn

function varargout = srivcstruc (varargin)
  varargout = contsid_guard ("srivcstruc", @srivcstruc_body, nargout, varargin);
endfunction

function [V, info, varargout] = srivcstruc_body (varargin)
  contsid_nargchk ("srivcstruc", nargin, nargout, [0 Inf], 2);
  fname = "srivcstruc";
  if (nargin < 3)
    error ("srivcstruc:badInput", "srivcstruc: expected ZE, ZV and NN");
  endif
  ZE = varargin{1};
  ZV = varargin{2};
  NN = varargin{3};
  rest = varargin(4:end);
  if (! isa (ZE, "iddata"))
    error ("srivcstruc:badInput", "srivcstruc: ZE must be an iddata object");
  endif
  if (! isempty (ZV) && ! isa (ZV, "iddata"))
    error ("srivcstruc:badInput",
           "srivcstruc: ZV must be an iddata object or []");
  endif
  if (mod (numel (rest), 2) != 0)
    error ("srivcstruc:badOption",
           "srivcstruc: options come as name-value pairs");
  endif
  n0e = 1; n0v = 1; form = "auto"; ic = "z"; den = "auto";
  pass = {};
  for i = 1:2:numel (rest)
    name = rest{i};
    if (! ischar (name))
      error ("srivcstruc:badOption", "srivcstruc: option names are strings");
    endif
    switch (lower (name))
      case "n0e"
        n0e = rest{i+1};
      case "n0v"
        n0v = rest{i+1};
      case "nn"
        form = rest{i+1};
      case "denominator"
        den = rest{i+1};
        if (! ischar (den) || ! any (strcmpi (den, {"common", "different"})))
          error ("srivcstruc:badOption", ["srivcstruc: Denominator must ", ...
                 "be 'Common' or 'Different'"]);
        endif
        den = lower (den);
      case "initialcondition"
        ic = rest{i+1};
        if (! ischar (ic)
            || ! any (strcmpi (ic, {"e", "z", "estimate", "zero"})))
          error ("srivcstruc:badOption", ["srivcstruc: InitialCondition ", ...
                 "must be 'e' (estimate) or 'z' (from rest)"]);
        endif
        ic = lower (ic(1));
      otherwise
        pass(end+1:end+2) = rest(i:i+1);
    endswitch
  endfor
  ue = get (ZE, "InputData");
  ye = get (ZE, "OutputData");
  nu = columns (ue);
  if (! isempty (ZV))
    uv = get (ZV, "InputData");
    yv = get (ZV, "OutputData");
    if (columns (uv) != nu || columns (yv) != columns (ye))
      error ("srivcstruc:dimensionMismatch",
             "srivcstruc: ZV must have the inputs and outputs of ZE");
    endif
  endif
  check_start (n0e, rows (ye), "n0e");
  if (! isempty (ZV))
    check_start (n0v, rows (yv), "n0v");
    if (any (isnan ([yv(:); uv(:)])))
      error ("srivcstruc:badInput",
             ["srivcstruc: ZV holds missing samples (NaN); the validation ", ...
              "simulation needs every sample (give a ZV without the gap)"]);
    endif
  endif
  ## Missing samples of ZE: srivc bridges them and simulates the present
  ## ones, so the criteria on ZE use the present samples from n0e on.
  present_e = ! (isnan (ye) | any (isnan (ue), 2));
  used_e = present_e;
  used_e(1:n0e-1) = false;
  structures = expand (NN, nu, form, den);
  ## the sampling the initial state is fitted on: Ts, or the instants
  if (! isempty (ZV))
    tv = sampling (ZV, true (rows (yv), 1));
  elseif (ic == "e")
    te = sampling (ZE, present_e);       # the samples srivc simulates
  endif

  ns = rows (structures);
  V = NaN (ns, 2 + columns (structures) + 2);
  info = struct ("models", {cell(ns, 1)}, "converged", false (ns, 1),
                 "stable", false (ns, 1), "determined", false (ns, 1),
                 "status", {cell(ns, 1)}, "fit", NaN (ns, 1),
                 "x0", {cell(ns, 1)});
  for k = 1:ns
    nn = structures(k, :);
    V(k, 3:2+numel (nn)) = nn;
    try
      [M, ~, YIC, est] = quiet_srivc (ZE, nn, pass);
    catch err
      if (any (strcmp (err.identifier, {"srivc:badOption", "srivc:badInput"}))
          && isempty (strfind (err.message, "nn")))
        error (strrep (err.identifier, "srivc", "srivcstruc"), "%s",
               strrep (err.message, "srivc:", "srivcstruc:"));
      endif
      continue;                          # this structure cannot be fitted
    end_try_catch
    info.models{k} = M;
    ## srivc's own status record, not a second judgement
    info.status{k} = est.status;
    info.converged(k) = est.status.converged;
    info.stable(k) = est.status.stable;
    info.determined(k) = est.status.determined;
    if (isempty (ZV))
      ys = est.simulated;
      if (ic == "e")
        [ys, info.x0{k}] = free_response (M, ye(present_e), ys, te);
      endif
      y = ye(used_e);
      ys = ys(used_e(present_e));
    else
      ## the model as estimated: simc applies the levels it carries (srivc
      ## on a raw record), on ZV's own sampling and InterSample
      ys = simc (M, ZV);
      if (ic == "e")
        [ys, info.x0{k}] = free_response (M, yv, ys, tv);
      endif
      y = yv(n0v:end);
      ys = ys(n0v:end);
    endif
    RT2 = 1 - var (y - ys, 1) / var (y, 1);
    info.fit(k) = 100 * (1 - norm (y - ys) / norm (y - mean (y)));
    V(k, 1) = RT2;
    V(k, 2) = YIC;
    V(k, end-1) = log10 (est.condition);
    V(k, end) = numel (y);
  endfor
endfunction

function [M, RT2, YIC, info] = quiet_srivc (ZE, nn, pass)
  state = warning ("off", "srivc:notConverged");
  state2 = warning ("off", "srivc:unstable");
  unwind_protect
    [M, RT2, YIC, ~, ~, info] = srivc (ZE, nn, pass{:});
  unwind_protect_cleanup
    warning (state);
    warning (state2);
  end_unwind_protect
endfunction

## The model's output plus its free response fitted to y (comparec's
## InitialCondition 'e'); a model whose initial state cannot be
## estimated (unstable, static) keeps its output from rest, x0 = [].
function [ys, x0] = free_response (M, y, ys, t)
  x0 = [];
  try
    [ys, x0] = contsid_initial_state ("srivcstruc", M, y, ys, t);
  catch err
    if (! strcmp (err.identifier, "srivcstruc:badInput"))
      rethrow (err);
    endif
  end_try_catch
endfunction

## The sampling interval of Z, or the instants of the samples kept.
function t = sampling (Z, keep)
  [d, ~] = contsid_getdata ("srivcstruc", Z);
  t = d.Ts;
  if (! d.uniform || ! all (keep))
    t = d.t(keep);
  endif
endfunction

function check_start (n0, n, name)
  if (! isnumeric (n0) || ! isscalar (n0) || n0 != fix (n0) || n0 < 1
      || n0 > n - 10)
    error ("srivcstruc:badOption",
           "srivcstruc: %s must be an integer in 1..N-10", name);
  endif
endfunction

## The list of structures [nb nf nk] from NN.
function S = expand (NN, nu, form, den)
  ## the row layout: [nb_1..nb_m nf nk_1..nk_m] (one common denominator)
  ## or [nb_1..nb_m nf_1..nf_m nk_1..nk_m] (one per input); the same for
  ## one input
  wc = 1 + 2 * nu;
  wd = 3 * nu;
  w = columns (NN);
  if (! isnumeric (NN) || ! isreal (NN) || isempty (NN) || ndims (NN) > 2
      || ! any (w == [wc wd]) || any (! isfinite (NN(:)))
      || any (NN(:) != fix (NN(:))) || any (NN(:) < 0))
    error ("srivcstruc:badInput",
           ["srivcstruc: NN must have rows of non-negative integers, ", ...
            "[nb nf nk] with one nb and nk per input: %d columns ", ...
            "(a common denominator) or %d (one denominator per input)"],
           wc, wd);
  endif
  different = w == wd && nu > 1;
  if (strcmp (den, "common") && different
      || strcmp (den, "different") && nu > 1 && w != wd)
    error ("srivcstruc:badInput",
           ["srivcstruc: Denominator '%s' needs rows of %d columns ", ...
            "(NN has %d)"], den, merge (different, wc, wd), w);
  endif
  if (! ischar (form) || ! any (strcmpi (form, {"auto", "range", "list"})))
    error ("srivcstruc:badOption",
           "srivcstruc: NN form must be 'auto', 'range' or 'list'");
  endif
  range = strcmpi (form, "range") || (strcmpi (form, "auto") && rows (NN) == 2);
  if (! range)
    S = NN;
    return;
  endif
  lo = min (NN, [], 1);
  hi = max (NN, [], 1);
  axes = arrayfun (@(a, b) a:b, lo, hi, "UniformOutput", false);
  grids = cell (1, w);
  [grids{:}] = ndgrid (axes{:});
  S = cell2mat (cellfun (@(g) g(:), grids, "UniformOutput", false));
  nb = S(:, 1:nu);
  kf = nu + (1:(w - 2 * nu));           # the denominator column(s)
  nf = S(:, kf);
  ok = all (nf >= 1, 2) & all (nb <= nf + 1, 2) & sum (nb, 2) >= 1;
  S = sortrows (S(ok, :), [kf, 1:nu, kf(end) + 1:w]);
  if (isempty (S))
    error ("srivcstruc:badInput", "srivcstruc: NN holds no valid structure");
  endif
endfunction

%!shared ZE, ZV, ZN
%! randn ("state", 3);
%! u = prbs (10, 8); Ts = 0.05; N = numel (u);
%! y = simc (idctm (4, [1 2.4 4]), u, Ts) + 0.1 * randn (N, 1);
%! h = floor (N / 2);
%! ZE = iddata (y(1:h), u(1:h), Ts);
%! ZV = iddata (y(h+1:end), u(h+1:end), Ts);
%! yn = y(h+1:end);
%! yn(10) = NaN;
%! ZN = iddata (yn, u(h+1:end), Ts);

%!test  # range form: the true structure [1 2 0] is among the best
%! [V, info] = srivcstruc (ZE, ZV, [1 1 0; 2 3 0]);
%! assert (columns (V), 7);
%! assert (V(:, 3:5), [1 1 0; 2 1 0; 1 2 0; 2 2 0; 1 3 0; 2 3 0]);
%! k = find (ismember (V(:, 3:5), [1 2 0], "rows"));
%! assert (V(k, 1) > 0.9);
%! assert (V(k, 1) > V(1, 1));           # better than first order
%! assert (all (V(:, 7) == V(1, 7)));
%! assert (info.converged(k) && info.stable(k));

%!test  # list form without validation data
%! V = srivcstruc (ZE, [], [1 2 0; 1 1 0], "NN", "list");
%! assert (V(:, 3:5), [1 2 0; 1 1 0]);
%! assert (V(1, 1) > V(2, 1));

%!error id=srivcstruc:badInput srivcstruc (ZE, [])
%!error id=srivcstruc:badInput srivcstruc (1, [], [1 2 0])
%!error id=srivcstruc:badInput srivcstruc (ZE, 3, [1 2 0])
%!error id=srivcstruc:badInput srivcstruc (ZE, [], [1 2])
%!error id=srivcstruc:badOption srivcstruc (ZE, [], [1 2 0], "NN", "bogus")
%!test  # a gap in ZE is bridged by srivc; criteria on the present samples
%! yg = get (ZE, "OutputData");
%! yg(40:45) = NaN;
%! V = srivcstruc (iddata (yg, get (ZE, "InputData"), get (ZE, "Ts")), [],
%!                 [1 2 0], "NN", "list");
%! assert (all (isfinite (V(1, :))));
%! assert (V(1, end), numel (yg) - 6);
%!test  # raw units: the fit (%) is that of the model with its levels
%! ## (without the levels a simulated lab record showed -24 % at a
%! ## validation R_T^2 of 0.99)
%! y0 = 20;                               # an operating point, 20 units
%! ye = get (ZE, "OutputData") + y0; yv = get (ZV, "OutputData") + y0;
%! ZEr = iddata (ye, get (ZE, "InputData"), get (ZE, "Ts"));
%! ZVr = iddata (yv, get (ZV, "InputData"), get (ZV, "Ts"));
%! [V, info] = srivcstruc (ZEr, ZVr, [1 2 0], "NN", "list");
%! M = info.models{1};
%! assert (M.Report.DataUsed.OutputOffset, y0, 0.5);
%! ys = simc (M, get (ZVr, "InputData") - M.Report.DataUsed.InputOffset,
%!            get (ZVr, "Ts"), "Levels", "ignore") ...
%!      + M.Report.DataUsed.OutputOffset;
%! assert (info.fit(1), 100 * (1 - norm (yv - ys) / norm (yv - mean (yv))),
%!         1e-9);
%! assert (V(1, 1) > 0.9);
%! ## with a zero-mean error, fit = 100 (1 - sqrt (1 - RT2))
%! assert (info.fit(1), 100 * (1 - sqrt (1 - V(1, 1))), 2);
%!test  # InitialCondition 'e': a validation record that does not start
%! ## at rest is judged with each model's initial state estimated; checked
%! ## against an independent least-squares fit of the free responses
%! ## (matrix exponential of the model's companion form, state [y; y'])
%! Ts = get (ZV, "Ts"); uv = get (ZV, "InputData"); N = numel (uv);
%! A0 = [0 1; -4 -2.4]; t = (0:N-1)' * Ts;
%! yfree = arrayfun (@(tk) [1 0] * expm (A0 * tk) * [3; -2], t);
%! ZVx = iddata (get (ZV, "OutputData") + yfree, uv, Ts);
%! V0 = srivcstruc (ZE, ZVx, [1 2 0], "NN", "list");
%! [V, info] = srivcstruc (ZE, ZVx, [1 2 0], "NN", "list",
%!                         "InitialCondition", "e");
%! M = info.models{1};
%! ys0 = simc (M, uv - M.Report.DataUsed.InputOffset, Ts, "Levels",
%!             "ignore") ...
%!       + M.Report.DataUsed.OutputOffset;
%! F = M.F / M.F(1);
%! A = [0 1; -F(3) -F(2)];
%! Phi = [arrayfun(@(tk) [1 0] * expm (A * tk) * [1; 0], t), ...
%!        arrayfun(@(tk) [1 0] * expm (A * tk) * [0; 1], t)];
%! yv = get (ZVx, "OutputData");
%! x0 = Phi \ (yv - ys0);
%! ys = ys0 + Phi * x0;
%! assert (info.x0{1}(:), x0, 1e-6 * norm (x0));
%! assert (V(1, 1), 1 - var (yv - ys, 1) / var (yv, 1), 1e-9);
%! assert (V0(1, 1), 1 - var (yv - ys0, 1) / var (yv, 1), 1e-9);
%! assert (V(1, 1) > 0.9 && V0(1, 1) < V(1, 1) - 0.05);
%! ## the state the record started in: [3; -2] plus that of the noise-free
%! ## system at the split (ZOH steps of its companion form)
%! ue = get (ZE, "InputData");
%! Md = expm ([A0, [0; 4]; 0 0 0] * Ts);
%! xs = [0; 0];
%! for k = 1:numel (ue)
%!   xs = Md(1:2, 1:2) * xs + Md(1:2, 3) * ue(k);
%! endfor
%! sd = 0.1 * sqrt (diag (inv (Phi' * Phi)));    # the noise's sd is 0.1
%! assert (abs (x0 - (xs + [3; -2])) < 4 * sd);
%!test  # without ZV, 'e' judges on ZE with the state estimated there
%! [V, info] = srivcstruc (ZE, [], [1 2 0; 1 1 0], "NN", "list",
%!                         "InitialCondition", "e");
%! Vz = srivcstruc (ZE, [], [1 2 0; 1 1 0], "NN", "list");
%! assert (! isempty (info.x0{1}) && ! isempty (info.x0{2}));
%! assert (all (V(:, 1) >= Vz(:, 1) - 1e-12));
%!error id=srivcstruc:badOption
%! srivcstruc (ZE, [], [1 2 0], "InitialCondition", "x")
%!test  # ZV is simulated on its own sampling: irregular instants, FOH;
%! ## R_T^2 equals comparec's on ZV (another path to the simulation; a
%! ## constant output level leaves R_T^2 unchanged)
%! randn ("state", 5); rand ("state", 5);
%! M0 = idpoly (1, 4, 1, 1, [1 2.4 4], "Ts", 0);
%! N = 600; t = cumsum (0.04 + 0.02 * rand (N, 1));
%! u = sign (sin (0.7 * t) + 0.3 * randn (N, 1));
%! y = simc (M0, iddata ([], u, "SamplingInstants", t)) + 0.02 * randn (N, 1);
%! Z = iddata (y, u, "SamplingInstants", t);
%! Ts = 0.05; uf = prbs (9, 8); Nf = numel (uf); h = floor (Nf / 2);
%! yf = simc (M0, iddata ([], uf, Ts, "InterSample", "foh"));
%! ZF = iddata (yf + 0.02 * randn (Nf, 1), uf, Ts, "InterSample", "foh");
%! for c = {{Z(1:300), Z(301:600)}, {ZF(1:h), ZF(h+1:Nf)}}
%!   [ze, zv] = deal (c{1}{:});
%!   for ic = {"z", "e"}
%!     [V, info] = srivcstruc (ze, zv, [1 2 0], "NN", "list",
%!                             "InitialCondition", ic{1});
%!     M = info.models{1};
%!     zvu = set (zv, "InputData",
%!                get (zv, "InputData") - M.Report.DataUsed.InputOffset);
%!     [~, ci] = comparec (zvu, M, "InitialCondition", ic{1},
%!                         "Levels", "ignore");
%!     assert (V(1, 1), ci.RT2, 1e-9);
%!     assert (V(1, 1) > 0.9);
%!   endfor
%! endfor
%!test  # two inputs, one denominator each (3m columns, CONTSID's
%! ## 'Different'): the true structure is recognised, R_T^2 equals
%! ## comparec's, the range expands per input
%! randn ("state", 11);
%! Ts = 0.05; u1 = prbs (10, 6); N = numel (u1); u2 = prbs (10, 9)(1:N);
%! M0 = idpoly (1, {4, [1 2]}, 1, 1, {[1 2.4 4], [1 3]}, "Ts", 0);
%! y = simc (M0, iddata ([], [u1 u2], Ts)) + 0.05 * randn (N, 1);
%! h = floor (N / 2);
%! Z1 = iddata (y(1:h), [u1(1:h) u2(1:h)], Ts);
%! Z2 = iddata (y(h+1:end), [u1(h+1:end) u2(h+1:end)], Ts);
%! [V, info] = srivcstruc (Z1, Z2, [1 2 2 1 0 0; 1 1 1 1 0 0], "NN", "list",
%!                         "Denominator", "Different");
%! assert (columns (V), 10);
%! assert (V(:, 3:8), [1 2 2 1 0 0; 1 1 1 1 0 0]);
%! assert (V(1, 1) > 0.99 && V(1, 1) > V(2, 1));
%! M = info.models{1};
%! [~, ci] = comparec (set (Z2, "InputData", get (Z2, "InputData")
%!                     - M.Report.DataUsed.InputOffset), M,
%!                     "Levels", "ignore");
%! assert (V(1, 1), ci.RT2, 1e-9);
%! S = srivcstruc (Z1, [], [1 1 1 1 0 0; 1 2 2 2 0 0]);
%! assert (S(:, 3:8), [1 1 1 1 0 0; 1 2 1 1 0 0; 1 1 1 2 0 0;
%!                     1 2 1 2 0 0; 1 1 2 1 0 0; 1 2 2 1 0 0;
%!                     1 1 2 2 0 0; 1 2 2 2 0 0]);
%!error id=srivcstruc:badInput
%! Z = iddata (randn (200, 1), randn (200, 2), 0.1);
%! srivcstruc (Z, [], [1 1 2 2 0 0], "Denominator", "Common");
%!error id=srivcstruc:badInput
%! Z = iddata (randn (200, 1), randn (200, 2), 0.1);
%! srivcstruc (Z, [], [1 1 2 0 0], "Denominator", "Different");
%!error id=srivcstruc:badOption
%! srivcstruc (ZE, [], [1 2 0], "Denominator", "Same")
%!error id=srivcstruc:badInput srivcstruc (ZE, ZN, [1 2 0])
%!error id=srivcstruc:badOption srivcstruc (ZE, [], [1 2 0], "n0e", 0)
%!error id=srivcstruc:badOption srivcstruc (ZE, [], [1 2 0], "n0e")
%!error id=srivcstruc:dimensionMismatch srivcstruc (ZE, iddata (randn (50, 1), randn (50, 2), 0.1), [1 2 0])

%!demo
%! u = prbs (10, 8); Ts = 0.05; N = numel (u);
%! y = simc (idctm (4, [1 2.4 4]), u, Ts) + 0.1 * randn (N, 1);
%! h = floor (N / 2);
%! ZE = iddata (y(1:h), u(1:h), Ts);
%! ZV = iddata (y(h+1:end), u(h+1:end), Ts);
%! V = srivcstruc (ZE, ZV, [1 1 0; 3 3 0]);
%! selcstruc (V, "NberOfModels", 5)

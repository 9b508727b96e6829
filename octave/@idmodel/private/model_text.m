## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{txt} =} model_text (@var{P}, @var{sd})
## The text that @code{display} (@var{sd} false) and @code{present}
## (@var{sd} true: each estimated coefficient followed by
## "(+/- standard deviation)") print for the model struct @var{P}, laid
## out as the System Identification Toolbox prints it.
## @end deftypefn

function txt = model_text (P, with_sd)
  [p, names] = pvec_of (P);
  sd = NaN (size (p));
  if (with_sd && ! isempty (P.cov))
    sd = sqrt (max (diag (P.cov), 0));
  endif
  ct = P.Ts == 0;
  L = {};
  switch (P.kind)
    case "idpoly"
      L = poly_lines (P, sd, ct);
    case "idtf"
      L = tf_lines (P, sd, ct);
    case "idproc"
      L = proc_lines (P, sd);
    case "idss"
      L = ss_lines (P, sd, ct);
    case "idfrd"
      w = P.par.Frequency;
      L{end+1} = sprintf (["IDFRD model.\nContains Frequency Response ", ...
                           "Data for %d output(s) and %d input(s)."],
                          P.ny, P.nu);
      L{end+1} = sprintf (["Response data is available at %d frequency ", ...
                           "points, ranging from %.4g rad/s to %.4g rad/s."],
                          numel (w), min (w), max (w));
  endswitch
  if (any (P.InputDelay != 0) && ! strcmp (P.kind, "idproc"))
    L{end+1} = sprintf ("Input delays (%s): %s", unit (P),
                        num2str (P.InputDelay(:).', "%.4g "));
  endif
  if (! isempty (P.legacy.nk) && any (P.legacy.nk))
    L{end+1} = sprintf ("Input delays (samples of the data): %s",
                        num2str (P.legacy.nk, "%d "));
  endif
  if (P.Ts > 0)
    L{end+1} = sprintf ("Sample time: %g seconds", P.Ts);
  endif
  if (! strcmp (P.kind, "idfrd"))
    L{end+1} = "";
    L{end+1} = "Parameterization:";
    nfree = numel (p);
    if (strcmp (P.kind, "idtf"))
      ## the IODelay entries of getpvec are free only when estimated
      nd = numel (P.par.IODelay);
      nfree -= sum (! (sd(end-nd+1:end) > 0));
    endif
    L{end+1} = sprintf ("   Number of free coefficients: %d", nfree);
    L{end+1} = ["   Use ""polydata"", ""getpvec"", ""getcov"" for ", ...
                "parameters and their uncertainties."];
  endif
  L{end+1} = "";
  L{end+1} = "Status:";
  R = P.Report;
  L{end+1} = R.Status;
  if (! isempty (R.Termination.Iterations) && R.Termination.Iterations > 0)
    conv = "";
    if (! isempty (R.Termination.Converged) && ! R.Termination.Converged)
      conv = " (not converged)";
    endif
    L{end+1} = sprintf ("Number of iterations: %d%s",
                        R.Termination.Iterations, conv);
  endif
  F = R.Fit;
  if (! isempty (F.FitPercent))
    L{end+1} = sprintf ("Fit to estimation data: %.4g%%", F.FitPercent);
  endif
  parts = {};
  for f = {"LossFcn", "FPE", "MSE"}
    if (! isempty (F.(f{1})))
      parts{end+1} = sprintf ("%s: %.4g", f{1}, F.(f{1}));
    endif
  endfor
  if (! isempty (parts))
    L{end+1} = strjoin (parts, ", ");
  endif
  ## The levels the model carries (help idpoly): simc, sim, comparec and
  ## residc simulate it at them, y - c = M (u - d).
  U = R.DataUsed;
  lev = {};
  for f = {"InputOffset", "OutputOffset"}
    if (isfield (U, f{1}) && ! isempty (U.(f{1})) && any (U.(f{1})(:)))
      lev{end+1} = sprintf ("%s = %s", f{1}, mat2str (U.(f{1})(:).', 5));
    endif
  endfor
  if (! isempty (lev))
    L{end+1} = ["Levels (y - OutputOffset = M (u - InputOffset)): ", ...
                strjoin(lev, ", ")];
  endif
  txt = strjoin (L, "\n");
endfunction

function u = unit (P)
  u = "seconds";
  if (P.Ts > 0)
    u = "samples";
  endif
endfunction

## One polynomial as text, coefficients with "(+/- sd)" where known.
## ct: descending powers of s (c(1) is the highest); otherwise ascending
## powers of z^-1.  The first coefficient of a monic polynomial is fixed.
function s = poly_str (c, sd, ct, var)
  n = numel (c);
  terms = {};
  for i = 1:n
    if (ct)
      k = n - i;
      pw = power_str (var, k);
    else
      k = i - 1;
      pw = power_str ("z^-", k);
    endif
    v = c(i);
    if (v == 0 && isnan (sd(i)) && n > 1)
      continue;
    endif
    if (isnan (sd(i)))
      coef = sprintf ("%.4g", abs (v));
      if (abs (v) == 1 && ! isempty (pw))
        coef = "";
      endif
    else
      coef = sprintf ("%.4g (+/- %.4g)", abs (v), sd(i));
    endif
    t = strtrim ([coef, " ", pw]);
    if (isempty (terms))
      if (v < 0)
        t = ["-", t];
      endif
    else
      t = [merge(v < 0, "- ", "+ "), t];
    endif
    terms{end+1} = t;
  endfor
  if (isempty (terms))
    terms = {"0"};
  endif
  s = strjoin (terms, " ");
endfunction

function pw = power_str (var, k)
  if (strcmp (var, "z^-"))
    if (k == 0)
      pw = "";
    else
      pw = sprintf ("z^-%d", k);
    endif
  elseif (k == 0)
    pw = "";
  elseif (k == 1)
    pw = var;
  else
    pw = sprintf ("%s^%d", var, k);
  endif
endfunction

function L = poly_lines (P, sd, ct)
  s = P.par;
  v = merge (ct, "s", "z");
  tm = merge (ct, "Continuous-time", "Discrete-time");
  hasA = numel (s.A) > 1;
  hasC = numel (s.C) > 1;
  hasD = numel (s.D) > 1;
  hasF = any (cellfun ("numel", s.F) > 1);
  if (! hasA && ! hasC && ! hasD)
    kind = "OE";
  elseif (hasA && ! hasF && ! hasC && ! hasD)
    kind = "ARX";
  elseif (hasA && hasC && ! hasF && ! hasD)
    kind = "ARMAX";
  elseif (! hasA && (hasC || hasD) && hasF)
    kind = "BJ";
  else
    kind = "polynomial";
  endif
  ## A hybrid model (rivc): continuous B/F, C/D in q^-1 at the noise
  ## model's sampling interval (Report.Parameters.NoiseModel.Ts).
  noise_ts = 0;
  if (ct && (hasC || hasD))
    noise_ts = hybrid_noise_ts (P);
  endif
  if (noise_ts > 0)
    kind = "hybrid BJ";
  endif
  terms = {};
  for j = 1:P.nu
    bj = merge (P.nu > 1, sprintf ("B%d", j), "B");
    fj = merge (P.nu > 1, sprintf ("F%d", j), "F");
    uj = merge (P.nu > 1, sprintf ("u%d(t)", j), "u(t)");
    if (numel (s.F{j}) > 1)
      terms{end+1} = sprintf ("[%s(%s)/%s(%s)]%s", bj, v, fj, v, uj);
    else
      terms{end+1} = sprintf ("%s(%s)%s", bj, v, uj);
    endif
  endfor
  noise = "e(t)";
  if (noise_ts > 0)
    noise = "[C(z)/D(z)]e(t)";
  elseif (hasC || hasD)
    noise = sprintf ("[C(%s)/D(%s)]e(t)", v, v);
  endif
  terms{end+1} = noise;
  lhs = merge (hasA, sprintf ("A(%s)y(t)", v), "y(t)");
  L = {sprintf("%s %s model:  %s = %s", tm, kind, lhs,
               strjoin (terms, " + "))};
  k = 0;
  [p, names] = pvec_of (P);
  function add (label, c, fixed_first, discrete)
    m = numel (c) - fixed_first;
    e = [NaN(1, fixed_first), sd(k+1:k+m).'];
    k += m;
    if (nargin > 3 && discrete)
      L{end+1} = sprintf ("  %s(z) = %s", label, poly_str (c, e, false, "z"));
    else
      L{end+1} = sprintf ("  %s(%s) = %s", label, v, poly_str (c, e, ct, v));
    endif
  endfunction
  if (hasA)
    add ("A", s.A, 1);
  else
    k += numel (s.A) - 1;
  endif
  for j = 1:P.nu
    add (merge (P.nu > 1, sprintf ("B%d", j), "B"), s.B{j}, 0);
  endfor
  if (hasC)
    add ("C", s.C, 1, noise_ts > 0);
  else
    k += numel (s.C) - 1;
  endif
  if (hasD)
    add ("D", s.D, 1, noise_ts > 0);
  else
    k += numel (s.D) - 1;
  endif
  if (noise_ts > 0)
    L{end+1} = sprintf (["  (C, D: discrete-time noise model in z^-1 = " ...
                         "q^-1, Ts = %g)"], noise_ts);
  endif
  for j = 1:P.nu
    if (numel (s.F{j}) > 1)
      add (merge (P.nu > 1, sprintf ("F%d", j), "F"), s.F{j}, 1);
    endif
  endfor
  if (any (s.IODelay != 0))
    L{end+1} = sprintf ("  I/O delays: %s", num2str (s.IODelay, "%.4g "));
  endif
endfunction

## The noise model's sampling interval of a hybrid model, else 0.
function ts = hybrid_noise_ts (P)
  ts = 0;
  if (isfield (P, "Report") && isstruct (P.Report)
      && isfield (P.Report, "Parameters") && isstruct (P.Report.Parameters)
      && isfield (P.Report.Parameters, "NoiseModel")
      && isstruct (P.Report.Parameters.NoiseModel)
      && isfield (P.Report.Parameters.NoiseModel, "Ts"))
    v = P.Report.Parameters.NoiseModel.Ts;
    if (isnumeric (v) && isscalar (v) && v > 0)
      ts = v;
    endif
  endif
endfunction

function L = tf_lines (P, sd, ct)
  s = P.par;
  v = merge (ct, "s", "z");
  L = {sprintf("%s identified transfer function.",
               merge (ct, "Continuous-time", "Discrete-time"))};
  nb = cellfun ("numel", s.Numerator);
  nf = cellfun ("numel", s.Denominator) - 1;
  offs_b = [0; cumsum(nb(:))];
  offs_f = sum (nb(:)) + [0; cumsum(nf(:))];
  for k = 1:numel (s.Numerator)
    [i, j] = ind2sub (size (s.Numerator), k);
    num = poly_str (s.Numerator{k}, sd(offs_b(k)+1:offs_b(k+1)).', true, v);
    den = poly_str (s.Denominator{k},
                    [NaN, sd(offs_f(k)+1:offs_f(k+1)).'], true, v);
    if (numel (s.Numerator) > 1)
      L{end+1} = sprintf ("  From input %d to output %d:", j, i);
    endif
    w = max (numel (num), numel (den));
    L{end+1} = ["  ", blanks(floor ((w - numel (num)) / 2)), num];
    dl = ["  ", repmat("-", 1, w)];
    if (s.IODelay(k) != 0)
      sdd = sd(offs_f(end) + k);
      if (ct && sdd > 0)
        dl = [dl, sprintf("  exp(-%.4g (+/- %.4g)*s)", s.IODelay(k), sdd)];
      elseif (ct)
        dl = [dl, sprintf("  exp(-%.4g*s)", s.IODelay(k))];
      else
        dl = [dl, sprintf("  z^-%d", s.IODelay(k))];
      endif
    endif
    L{end+1} = dl;
    L{end+1} = ["  ", blanks(floor ((w - numel (den)) / 2)), den];
  endfor
endfunction

function L = proc_lines (P, sd)
  s = P.par;
  [names, np, flags] = proc_names (s.Type);
  num = "Kp";
  if (flags.Z)
    num = "Kp * (1 + Tz*s)";
  endif
  den = {};
  if (flags.I)
    den{end+1} = "s";
  endif
  if (flags.U)
    den{end+1} = "(1 + 2*Zeta*Tw*s + (Tw*s)^2)";
    if (np == 3)
      den{end+1} = "(1 + Tp3*s)";
    endif
  else
    for i = 1:np
      den{end+1} = sprintf ("(1 + Tp%d*s)", i);
    endfor
  endif
  if (isempty (den))
    den = {"1"};
  endif
  den = strjoin (den, "");
  w = max (numel (num), numel (den));
  delay = "";
  if (flags.D)
    delay = " * exp(-Td*s)";
  endif
  L = {"Process model with transfer function:", ...
       ["           ", blanks(floor ((w - numel (num)) / 2)), num], ...
       ["  G(s) = ", repmat("-", 1, w + 2), delay], ...
       ["           ", blanks(floor ((w - numel (den)) / 2)), den], ""};
  for i = 1:numel (names)
    val = s.Structure.(names{i}).Value;
    if (isnan (sd(i)))
      L{end+1} = sprintf ("        %4s = %.5g", names{i}, val);
    else
      L{end+1} = sprintf ("        %4s = %.5g (+/- %.4g)", names{i}, val,
                          sd(i));
    endif
  endfor
endfunction

function L = ss_lines (P, sd, ct)
  s = P.par;
  if (ct)
    L = {"Continuous-time identified state-space model:", ...
         "    dx/dt = A x(t) + B u(t) + K e(t)"};
  else
    L = {"Discrete-time identified state-space model:", ...
         "  x(t+Ts) = A x(t) + B u(t) + K e(t)"};
  endif
  L{end+1} = "     y(t) = C x(t) + D u(t) + e(t)";
  for f = {"A", "B", "C", "D"}
    L{end+1} = "";
    L{end+1} = sprintf ("  %s = ", f{1});
    rows_ = strsplit (strtrim (disp (s.(f{1}))), "\n");
    for r = 1:numel (rows_)
      L{end+1} = ["    ", rows_{r}];
    endfor
  endfor
endfunction

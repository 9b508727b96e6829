## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn  {} {@var{T} =} residtrace_effects_random ()
## @deftypefnx {} {@var{T} =} residtrace_effects_random (@var{ncases})
## @deftypefnx {} {@var{T} =} residtrace_effects_random (@var{ncases}, @var{seed}, @var{outdir}, @var{which})
## How often @code{residtrace} names the right effect, on many random
## records with one undeclared effect each. For each effect of the list
## below @var{ncases} records (default 2) are drawn: a random stable plant
## of order 1 to 3 (real or complex poles with moduli in [0.5, 4] rad/s,
## sometimes a zero, a random gain and sign), a random input (PRBS,
## random-phase multisine or a staircase of random levels) whose band
## follows the plant's, a sampling interval that puts the fastest pole
## at 0.03 to 0.1 rad per sample, white measurement noise at 15 to 30 dB
## and a random size of the effect within a physically sensible range.
## Records are simulated exactly for a held input, with 20 sub-steps per
## sample (a transport delay of any length, not a whole number of
## samples; friction held over a sub-step). The model given to
## @code{residtrace} is the dynamics (B, F) of @code{srivc}'s fit of the
## plain linear structure on the estimation record with its means
## removed; the validation record is a new input and noise
## realisation (the continuation of the experiment for the drift).
##
## Effects and the name counted right:
## @table @asis
## @item none
## a linear plant (right: 'none').
## @item offset
## a constant added to the input, an actuator's bias ('offset'; an output
## offset of a record at rest away from zero is the record's level,
## estimated with the baseline).
## @item coulomb
## a mass on a spring with viscous and Coulomb friction, position
## measured, or a rotating inertia, velocity measured ('coulomb').
## @item delay
## a transport delay of 1.5 to 8 samples ('delay').
## @item sinusoid
## an additive sinusoid at a random frequency ('sinusoid').
## @item saturation
## the output limited at one or both ends ('saturation').
## @item dead_zone
## a dead zone on the input ('static_nonlinearity').
## @item order
## a pole of the plant the model lacks ('order').
## @item drift
## a pole and the gain drifting by 20 to 40 % along the experiment
## ('drift').
## @item colored_noise
## AR(1) measurement noise ('colored_noise').
## @end table
##
## Prints each case and writes @var{outdir}/residtrace_effects_random.md
## (default "results"): per effect, how often it was named first, and
## what it was confused with. @var{seed} (default 20261129) fixes every
## draw; @var{which} the effect names to run, a cell or a comma-separated
## string (default all). @var{C} holds the records (y, u, yv, uv, Ts, the
## structure nn, a description); with @var{records_only} true they are
## only drawn, not analysed. A negative @var{ncases} -k draws the k-th
## record of each effect alone (each record has a seed of its own).
## The rules of residtrace are not tuned on these records: they are a
## check.
## @end deftypefn

function [T, C] = residtrace_effects_random (ncases = 2, seed = 20261129,
                                             outdir = "results", which = {},
                                             records_only = false)
  demo_prepare (outdir);
  if (ischar (which))
    which = strsplit (which, ",");
  endif
  ks = 1:ncases;
  if (ncases < 0)
    ks = -ncases;                 # that record alone (each has its seed)
  endif
  effects = {"none", "offset", "coulomb", "delay", "sinusoid", ...
             "saturation", "dead_zone", "order", "drift", "colored_noise"};
  right = {"none", "offset", "coulomb", "delay", "sinusoid", "saturation", ...
           "static_nonlinearity", "order", "drift", "colored_noise"};
  T = struct ("effect", {}, "case", {}, "found", {}, "ok", {}, "rivals", {},
              "text", {}, "rmse_before", {}, "rmse_after", {}, "seconds", {},
              "error", {}, "ranking", {});
  C = struct ("y", {}, "yv", {}, "u", {}, "uv", {}, "Ts", {}, "nn", {},
              "text", {}, "effect", {});
  ws = warning ("off", "all");
  restore = onCleanup (@() warning (ws));
  for e = 1:numel (effects)
    if (! isempty (which) && ! any (strcmp (which, effects{e})))
      continue;
    endif
    for k = ks
      s = seed + 1000 * e + k;
      randn ("state", s); rand ("state", s);
      c = feval (["case_" effects{e}]);
      c.effect = effects{e};
      C(end+1) = c;
      if (records_only)
        continue;
      endif
      t0 = tic ();
      err = "";
      found = "error"; riv = ""; rb = NaN; ra = NaN; rk = "";
      try
        ## the user's model: the dynamics of the plain linear structure
        ## fitted by srivc on the estimation record with its means
        ## removed (without the levels srivc may estimate with them: those
        ## are kept by residtrace's baseline, and an offset would not be
        ## an effect)
        M = srivc (iddata (c.y - mean (c.y), c.u - mean (c.u), c.Ts), c.nn);
        M = idctm (M.B, M.F);
        R = residtrace (iddata (c.y, c.u, c.Ts), M,
                        "validation", iddata (c.yv, c.uv, c.Ts),
                        "iterate", 1);
        found = R.effect;
        if (! isempty (R.rivals))
          riv = strjoin (unique ({R.rivals.effect}), "/");
        endif
        rb = R.rmse_before; ra = R.rmse_after;
        rk = ranking_text (R.ranking);
      catch ex
        err = sprintf ("%s (%s)", ex.message, ex.identifier);
      end_try_catch
      T(end+1) = struct ("effect", effects{e}, "case", k, "found", found,
                         "ok", strcmp (found, right{e}), "rivals", riv,
                         "text", c.text, "rmse_before", rb,
                         "rmse_after", ra, "seconds", toc (t0),
                         "error", err, "ranking", rk);
      printf ("%-14s %2d  %-20s %s  %s  [%s]%s  (%.0f s)\n", effects{e}, k,
              found, ifelse (T(end).ok, "ok  ", "MISS"), c.text,
              riv, ifelse (isempty (err), "", ["  " err]), T(end).seconds);
      printf ("      %s\n", rk);
      fflush (stdout);
    endfor
  endfor
  if (! records_only)
    write_table (T, effects, right, outdir, ncases, seed);
  endif
endfunction

function write_table (T, effects, right, outdir, ncases, seed)
  fid = fopen (fullfile (outdir, "residtrace_effects_random.md"), "w");
  fprintf (fid, "%d random records per effect, seed %d.\n\n", abs (ncases),
           seed);
  fprintf (fid, ["| true effect | right name | named right | named ", ...
                 "instead (count) |\n|---|---|---|---|\n"]);
  tot = 0; n = 0;
  for e = 1:numel (effects)
    k = strcmp ({T.effect}, effects{e});
    if (! any (k))
      continue;
    endif
    t = T(k);
    wrong = {t(! [t.ok]).found};
    parts = {};
    for w = unique (wrong)
      parts{end+1} = sprintf ("%s (%d)", w{1}, sum (strcmp (wrong, w{1})));
    endfor
    fprintf (fid, "| %s | %s | %d / %d | %s |\n", effects{e}, right{e},
             sum ([t.ok]), numel (t), strjoin (parts, ", "));
    tot += sum ([t.ok]); n += numel (t);
  endfor
  fprintf (fid, "| all | | %d / %d | |\n", tot, n);
  fprintf (fid, ["\n| true effect | case | named first | rivals | ", ...
                 "record | RMSE before -> after | time (s) |\n", ...
                 "|---|---|---|---|---|---|---|\n"]);
  for t = T
    fprintf (fid, "| %s | %d | %s | %s | %s | %.4g -> %.4g | %.0f |\n",
             t.effect, t.case, t.found, t.rivals, t.text, t.rmse_before,
             t.rmse_after, t.seconds);
  endfor
  fclose (fid);
endfunction

## The significant candidates of the first pass, best first, with their
## scores and p-values.
function s = ranking_text (r)
  s = "";
  if (isempty (r))
    return;
  endif
  r = r([r.significant]);
  parts = arrayfun (@(x) sprintf ("%s %.3g (p %.2g, %s)", x.effect, x.score,
                                  x.p, x.variant), r,
                    "UniformOutput", false);
  s = strjoin (parts, "; ");
endfunction

function s = ifelse (c, a, b)
  if (c)
    s = a;
  else
    s = b;
  endif
endfunction

## ---- random draws ----------------------------------------------------

function x = unif (a, b)
  x = a + (b - a) * rand ();
endfunction

## A random stable plant: [A, B, C] in observable canonical form of
## B(p)/F(p), order n (1 .. 3 unless given), and its F, B.
function P = plant (n)
  if (nargin < 1)
    n = randi (3);
  endif
  p = [];
  while (numel (p) < n)
    if (n - numel (p) >= 2 && rand () < 0.5)
      wn = unif (0.8, 4); z = unif (0.2, 0.9);
      p = [p; -z * wn + 1i * wn * sqrt(1 - z^2); -z * wn - 1i * wn * sqrt(1 - z^2)];
    else
      p(end+1, 1) = -unif (0.5, 4);
    endif
  endwhile
  F = real (poly (p));
  b = 1;
  if (n >= 2 && rand () < 0.4)
    b = [1 / unif(0.5, 6), 1];              # a zero in the left half-plane
  endif
  g = unif (0.5, 5) * sign (rand () - 0.3);
  b = g * F(end) * b / b(end);              # DC gain g
  P = struct ("F", F, "B", b, "n", n, "wmax", max (abs (p)),
              "wmin", min (abs (p)));
endfunction

function Ts = sample_time (P)
  Ts = unif (0.03, 0.1) / P.wmax;
endfunction

## Input of N samples, unit standard deviation, band about bw rad/s.
function [u, typ] = input_signal (N, Ts, bw, typ)
  types = {"prbs", "multisine", "steps"};
  if (nargin < 4)
    typ = types{randi (3)};
  endif
  switch (typ)
    case "prbs"
      p = max (1, round (1 / (bw * Ts)));
      u = prbs (12, p, [-1 1], N + 1000);
      u = u(1 + randi (1000):end)(1:N);
    case "multisine"
      T = N * Ts;
      k = 1:max (2, floor (bw * T / (2 * pi)));
      t = (0:N-1)' * Ts;
      u = sum (cos (2 * pi * t * k / T + 2 * pi * rand (1, numel (k))), 2);
    case "steps"
      hold_ = 1 / bw;
      u = residtrace_levels (N, Ts, 2 * hold_, 10 * hold_, -1, 1);
  endswitch
  u = (u - mean (u)) / std (u);
endfunction

## Exact simulation for the input held over each sample, S sub-steps per
## sample: x' = A x + B (u(t - tau) - fric (x)), y = C x.
function y = sim_fine (P, u, Ts, tau, fric)
  if (nargin < 4)
    tau = 0;
  endif
  if (nargin < 5)
    fric = [];
  endif
  [A, B, C] = canon (P);
  S = 20; h = Ts / S;
  n = rows (A);
  E = expm ([A, B; zeros(1, n + 1)] * h);
  Ad = E(1:n, 1:n); Bd = E(1:n, n+1);
  N = numel (u);
  uf = kron (u(:), ones (S, 1));
  d = round (tau / h);
  uf = [repmat(u(1), d, 1); uf(1:end-d)];
  x = zeros (n, 1);
  if (isfield (P, "x0"))
    x = P.x0;
  endif
  y = zeros (N, 1);
  i = 0;
  for k = 1:N
    y(k) = C * x;
    for s = 1:S
      i++;
      f = uf(i);
      if (! isempty (fric))
        f -= fric (x);
      endif
      x = Ad * x + Bd * f;
    endfor
  endfor
endfunction

function [A, B, C] = canon (P)
  n = numel (P.F) - 1;
  A = [-P.F(2:end).', [eye(n - 1); zeros(1, n - 1)]];
  B = [zeros(n - numel (P.B), 1); P.B(:)];
  C = [1, zeros(1, n - 1)];
endfunction

function y = noisy (x, snr)
  y = x + randn (size (x)) * std (x) / 10 ^ (snr / 20);
endfunction

## Estimation and validation records of a plant with a map applied to
## the input (before) or output (after) of its linear part.
## (a delay of d samples)
function c = linear_case (P, snr, uin, yout, d)
  if (nargin < 3 || isempty (uin)) uin = @(u) u; endif
  if (nargin < 4 || isempty (yout)) yout = @(x) x; endif
  if (nargin < 5) d = 0; endif
  Ts = sample_time (P); N = 2000;
  tau = d * Ts;
  bw = P.wmax * unif (0.5, 2);
  [u, typ] = input_signal (N, Ts, bw);
  uv = input_signal (N, Ts, bw, typ);
  c.y = noisy (yout (sim_fine (P, uin (u), Ts, tau)), snr);
  c.yv = noisy (yout (sim_fine (P, uin (uv), Ts, tau)), snr);
  c.u = u; c.uv = uv; c.Ts = Ts;
  c.nn = [numel(P.B), numel(P.F) - 1, 0];
  c.text = sprintf ("order %d, %s, SNR %.0f dB", P.n, typ, snr);
endfunction

## ---- one record per effect -------------------------------------------

function c = case_none ()
  c = linear_case (plant (), unif (15, 30));
endfunction

## a bias of the actuator: a constant entering with the input (an
## output offset on a record at rest away from zero is the record's level,
## which residtrace estimates with the baseline, not an effect)
function c = case_offset ()
  P = plant (); snr = unif (15, 30);
  a = unif (0.2, 0.5) * sign (rand () - 0.5);
  c = linear_case (P, snr, @(u) u + a);
  c.text = sprintf ("input offset %.2f, %s", a, c.text);
endfunction

## m x'' + cv x' + k x = u - Fc sign(x') (position measured), or
## m v' + cv v = u - Fc sign(v) (velocity measured).
function c = case_coulomb ()
  snr = unif (20, 30);
  Fc = unif (0.15, 0.4);                   # input std 1
  if (rand () < 0.6)
    wn = unif (1, 4); z = unif (0.2, 0.8); m = unif (0.5, 2);
    P = struct ("F", [1 2 * z * wn wn ^ 2], "B", 1 / m, "n", 2,
                "wmax", wn, "wmin", wn);
    what = "position";
  else
    a = unif (0.5, 4); m = unif (0.5, 2);
    P = struct ("F", [1 a], "B", 1 / m, "n", 1, "wmax", a, "wmin", a);
    what = "velocity";
  endif
  Ts = sample_time (P); N = 2000;
  bw = P.wmax * unif (0.5, 2);
  typ = {"multisine", "steps", "prbs"}{randi (3)};
  u = input_signal (N, Ts, bw, typ); uv = input_signal (N, Ts, bw, typ);
  ## in the observable form of 1/m / (p^2 + f1 p + f2): x1 = position,
  ## x2 = velocity + f1 position; the friction enters through B = [0; 1/m]
  if (P.n == 2)
    fric = @(x) Fc * sign (x(2) - P.F(2) * x(1));
  else
    fric = @(x) Fc * sign (x(1));
  endif
  c.y = noisy (sim_fine (P, u, Ts, 0, fric), snr);
  c.yv = noisy (sim_fine (P, uv, Ts, 0, fric), snr);
  c.u = u; c.uv = uv; c.Ts = Ts;
  c.nn = [1, P.n, 0];
  c.text = sprintf ("Coulomb %.2f, %s, order %d, %s, SNR %.0f dB", Fc, what,
                    P.n, typ, snr);
endfunction

function c = case_delay ()
  P = plant ();
  d = unif (1.5, 8);
  c = linear_case (P, unif (15, 30), [], [], d);
  c.text = sprintf ("delay %.2f samples, %s", d, c.text);
endfunction

function c = case_sinusoid ()
  P = plant (); snr = unif (15, 30);
  c = linear_case (P, snr);
  N = numel (c.y); T = N * c.Ts;
  f = exp (unif (log (10 / T), log (0.15 / c.Ts)));   # Hz
  A = unif (0.1, 0.4) * std (c.y);
  t = (0:N-1)' * c.Ts;
  c.y += A * sin (2 * pi * f * t + 2 * pi * rand ());
  c.yv += A * sin (2 * pi * f * t + 2 * pi * rand ());
  c.text = sprintf ("sinusoid %.3g Hz, amplitude %.2f sd, %s", f,
                    A / std (c.y), c.text);
endfunction

function c = case_saturation ()
  P = plant (); snr = unif (20, 30);
  Ts = sample_time (P);
  ## levels from a noise-free run: at the 75 .. 92 % quantile of the
  ## output, at one end or both
  u0 = input_signal (2000, Ts, P.wmax);
  x0 = sort (sim_fine (P, u0, Ts));
  q = unif (0.75, 0.92);
  hi = x0(round (q * end));
  lo = -Inf;
  if (rand () < 0.5)
    lo = x0(round ((1 - q) * end));
  endif
  c = linear_case (P, snr, [], @(x) min (max (x, lo), hi));
  c.text = sprintf ("output limited to [%.3g, %.3g], %s", lo, hi, c.text);
endfunction

function c = case_dead_zone ()
  P = plant (); snr = unif (20, 30);
  d = unif (0.15, 0.5);                     # input std 1
  c = linear_case (P, snr, @(u) sign (u) .* max (abs (u) - d, 0));
  c.text = sprintf ("input dead zone +-%.2f, %s", d, c.text);
endfunction

function c = case_order ()
  P = plant (randi (2));
  pe = -unif (0.7, 2.5) * P.wmax;           # a pole the model lacks
  P.F = conv (P.F, [1 -pe]);
  P.B = P.B * -pe;
  n0 = P.n;
  P.n += 1;
  P.wmax = max (P.wmax, -pe);
  c = linear_case (P, unif (20, 30));
  c.nn = [numel(P.B), n0, 0];
  c.text = sprintf ("extra pole %.3g, %s", pe, c.text);
endfunction

## one experiment of 4000 samples: a pole and the gain drift linearly;
## the first half estimates, the second validates
function c = case_drift ()
  n = randi (2);
  P = plant (n);
  Ts = sample_time (P); N = 4000;
  bw = P.wmax * unif (0.5, 2);
  [u, typ] = input_signal (N, Ts, bw);
  r = unif (0.2, 0.4) * sign (rand () - 0.5);
  S = 20; h = Ts / S; x = zeros (n, 1); y = zeros (N, 1);
  for k = 1:N
    s = 1 + r * (k - 1) / (N - 1);
    Pk = P;
    Pk.F = P.F .* s .^ (0:n);               # every pole scaled by s
    Pk.B = P.B * s ^ n;
    [A, B, C] = canon (Pk);
    y(k) = C * x;
    E = expm ([A, B; zeros(1, n + 1)] * Ts);
    x = E(1:n, 1:n) * x + E(1:n, n+1) * u(k);
  endfor
  y = noisy (y, unif (20, 30));
  h = N / 2;
  c.y = y(1:h); c.u = u(1:h); c.yv = y(h+1:end); c.uv = u(h+1:end);
  c.Ts = Ts; c.nn = [numel(P.B), n, 0];
  c.text = sprintf ("poles drift %+.0f %%, order %d, %s", 100 * r, n, typ);
endfunction

function c = case_colored_noise ()
  P = plant ();
  c = linear_case (P, Inf);
  a = unif (0.85, 0.97);
  s = std (c.y) / 10 ^ (unif (12, 20) / 20) * sqrt (1 - a ^ 2);
  c.y += filter (1, [1 -a], s * randn (size (c.y)));
  c.yv += filter (1, [1 -a], s * randn (size (c.yv)));
  c.text = sprintf ("AR(1) noise a = %.2f, %s", a, c.text);
endfunction

## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{m} =} contsid_model (@var{fname}, @var{M})
## @deftypefnx {} {@var{m} =} contsid_model (@var{fname}, @var{M}, @var{Ts})
## @deftypefnx {} {@var{m} =} contsid_model (@var{fname}, @var{M}, @var{Ts}, @var{fractional})
## Reads a time-invariant model for the front-end @var{fname}: the one
## place where simc, comparec, residc, residtrace, bode4frozensys and
## bandwidthc learn what a model is.  @var{M} may be an @code{idpoly},
## @code{idtf}, @code{idproc} or @code{idss} (this toolbox's SITB
## classes, @code{idctm} included), a struct with fields @code{B},
## @code{F} and optionally @code{nk} (delays in samples), or a control
## package @code{tf} or @code{ss}.
##
## @var{m} is a struct with fields
## @table @code
## @item kind
## @qcode{"tf"} (B and F below) or @qcode{"ss"} (a, b, c, d below).
## @item ny, nu
## numbers of outputs and inputs.
## @item B, F
## ny-by-nu cells: numerator rows and monic denominator rows (descending
## powers of s; in discrete time the SITB q^-1 rows of an idpoly, z rows
## otherwise); the idpoly's A is multiplied into each F.
## @item common
## true when every F of an output is the same (one denominator).
## @item a, b, c, d
## the state-space matrices (kind "ss").
## @item delay
## ny-by-nu total delays in seconds (NaN when only @code{nk} is known).
## @item nk
## ny-by-nu delays in samples of the data: from a struct's or idctm's
## @code{nk}, or delay / @var{Ts} when @var{Ts} (the data's sampling
## interval) is given; [] otherwise.
## @item Ts
## the model's sampling time (0: continuous time).
## @item cov, theta
## the parameter covariance (getpvec order; [] if none) and CONTSID's
## theta [f b] (idpoly, struct and idctm only; [] otherwise).
## @end table
## Errors, with the identifier prefix @var{fname}: @code{badInput} (not a
## model, NaN parameters, a struct without B and F, a negative or
## non-integer nk), @code{notSupported} (frequency data; a delay that is
## not a whole number of samples of @var{Ts}).
## @end deftypefn

function m = contsid_model (fname, M, Ts, fractional)
  if (nargin < 3)
    Ts = [];
  endif
  if (nargin < 4)
    fractional = false;
  endif
  m = struct ("kind", "tf", "ny", 1, "nu", 0, "B", {{}}, "F", {{}},
              "common", true, "a", [], "b", [], "c", [], "d", [],
              "delay", [], "nk", [], "Ts", 0, "cov", [], "theta", []);
  if (isa (M, "idfrd"))
    error ([fname ":notSupported"],
           "%s: frequency response data (idfrd) cannot be simulated", fname);
  elseif (isa (M, "idss"))
    m.kind = "ss";
    [m.a, m.b, m.c, m.d] = deal (M.A, M.B, M.C, M.D);
    [m.ny, m.nu] = size (m.d);
    m.delay = totaldelay (M);
    m.Ts = M.Ts;
    m.cov = getcov (M);
  elseif (isa (M, "idmodel"))
    try
      [num, den] = tfdata (M);
    catch err
      error ([fname ":badInput"], "%s: %s", fname, err.message);
    end_try_catch
    m.Ts = M.Ts;
    if (isa (M, "idpoly") && m.Ts > 0)
      ## keep the q^-1 rows of a discrete-time idpoly
      [A, B, ~, ~, F] = polydata (M);
      if (! iscell (B))
        [B, F] = deal ({B}, {F});
      endif
      num = B;
      den = cellfun (@(f) conv (A, f), F, "UniformOutput", false);
    endif
    [m.B, m.F] = deal (num, den);
    [m.ny, m.nu] = size (num);
    m.delay = totaldelay (M);
    m.cov = getcov (M);
    if (isa (M, "idpoly"))
      m.theta = M.theta;
      if (m.Ts == 0 && ! any (m.delay(:)) && any (M.nk))
        m.nk = M.nk;                   # idctm delays in samples only
        m.delay = NaN (size (m.nk));
      endif
    endif
  elseif (isa (M, "tf") || isa (M, "ss"))
    if (isa (M, "ss"))
      m.kind = "ss";
      [m.a, m.b, m.c, m.d] = ssdata (M);
      [m.ny, m.nu] = size (m.d);
    else
      [m.B, m.F] = tfdata (M);
      [m.ny, m.nu] = size (m.B);
    endif
    m.Ts = max (get (M, "tsam"), 0);
    m.delay = zeros (m.ny, m.nu);
  elseif (isstruct (M))
    if (! isscalar (M) || ! all (isfield (M, {"B", "F"})))
      error ([fname ":badInput"], "%s: the model struct needs fields B and F",
             fname);
    endif
    B = M.B;
    if (! iscell (B))
      B = {B};
    endif
    F = M.F;
    if (! iscell (F))
      F = repmat ({F}, size (B));
    endif
    if (numel (F) != numel (B))
      error ([fname ":badInput"], "%s: one F per input, or one F for all",
             fname);
    endif
    m.B = B(:).';
    m.F = F(:).';
    m.nu = numel (B);
    m.delay = zeros (1, m.nu);
    m.theta = [];
    if (isfield (M, "nk") && ! isempty (M.nk))
      m.nk = M.nk;
      if (! isnumeric (m.nk) || ! isreal (m.nk) || numel (m.nk) != m.nu
          || any (! isfinite (m.nk)) || any (m.nk != fix (m.nk))
          || any (m.nk < 0))
        error ([fname ":badInput"],
               "%s: nk must be one integer >= 0 per input", fname);
      endif
      m.nk = double (m.nk(:).');
      m.delay = NaN (1, m.nu);
    endif
  else
    error ([fname ":badInput"],
           ["%s: the model must be an idpoly, idtf, idproc, idss (or ", ...
            "idctm), a struct with B and F, or a tf/ss; got a %s"],
           fname, class (M));
  endif
  if (strcmp (m.kind, "tf"))
    m = normalise_tf (fname, m);
  endif
  if (! isempty (Ts) && isempty (m.nk))
    m.nk = samples (fname, m.delay, Ts, fractional);
  endif
endfunction

function m = normalise_tf (fname, m)
  for k = 1:numel (m.F)
    f = m.F{k};
    b = m.B{k};
    if (! isnumeric (f) || ! isreal (f) || ! isvector (f) || isempty (f)
        || f(1) == 0 || any (! isfinite (f)))
      error ([fname ":badInput"],
             "%s: F must be a finite [1 a1 .. a_na] (leading term != 0)",
             fname);
    endif
    if (! isnumeric (b) || ! isreal (b) || (! isvector (b) && ! isempty (b))
        || any (! isfinite (b)))
      error ([fname ":badInput"], "%s: B must be a finite real row", fname);
    endif
    m.B{k} = double (b(:).') / f(1);
    m.F{k} = double (f(:).') / f(1);
  endfor
  m.common = true;
  for i = 1:m.ny
    for j = 2:m.nu
      m.common &= isequal (m.F{i, j}, m.F{i, 1});
    endfor
  endfor
endfunction

function nk = samples (fname, delay, Ts, fractional)
  if (all (delay(:) == 0))
    nk = zeros (size (delay));
    return;
  endif
  if (! (Ts > 0))
    error ([fname ":notSupported"],
           "%s: a model with delays needs uniformly sampled data", fname);
  endif
  nk = round (delay / Ts);
  if (fractional)
    exact = abs (nk - delay / Ts) <= 1e-9 * max (1, abs (nk));
    nk(! exact) = delay(! exact) / Ts;
    return;
  endif
  if (any (abs (nk(:) - delay(:) / Ts) > 1e-9 * max (1, abs (nk(:)))))
    error ([fname ":notSupported"],
           ["%s: the delays %s s are not whole multiples of the ", ...
            "sampling interval %g s"], fname, mat2str (delay, 4), Ts);
  endif
endfunction

## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{M} =} set_prop (@var{M}, @var{name}, @var{v}, @var{fname})
## Sets the property @var{name} (canonical spelling) of @var{M} to @var{v}
## after checking it; errors @code{@var{fname}:badInput} or
## @code{@var{fname}:dimensionMismatch}.  A change of the number of
## parameters drops the covariance.
## @end deftypefn

function M = set_prop (M, name, v, fname)
  [~, readonly] = model_props (M.kind);
  if (any (strcmp (name, readonly)))
    error ([fname ":badInput"], "%s: property '%s' of %s is read-only",
           fname, name, M.kind);
  endif
  np_before = numel (pvec_of (M));
  switch (name)
    case "Ts"
      if (! isnumeric (v) || ! isreal (v) || ! isscalar (v) || ! (v >= 0)
          || ! isfinite (v))
        error ([fname ":badInput"],
               "%s: Ts must be a finite scalar >= 0 (0: continuous time)",
               fname);
      endif
      M.Ts = double (v);
    case "InputDelay"
      M.InputDelay = check_delay (v, [M.nu, 1], "InputDelay", fname, M.Ts);
    case {"InputName", "InputUnit", "OutputName", "OutputUnit"}
      n = M.nu;
      if (strncmp (name, "Output", 6))
        n = M.ny;
      endif
      if (ischar (v))
        v = {v};
      endif
      if (! iscellstr (v) || numel (v) != n)
        error ([fname ":badInput"], "%s: %s must be %d string(s)", fname,
               name, n);
      endif
      M.(name) = v(:);
    case {"Name", "TimeUnit"}
      if (! ischar (v))
        error ([fname ":badInput"], "%s: %s must be a string", fname, name);
      endif
      M.(name) = v;
    case "Notes"
      if (! (ischar (v) || iscellstr (v)))
        error ([fname ":badInput"],
               "%s: Notes must be text (a string or a cell of strings)",
               fname);
      endif
      M.Notes = v;
    case "UserData"
      M.UserData = v;                   # the user's own, stored as given
    case "Report"
      M.Report = merge_report (M.Report, v, fname);
    case "noise_variance"
      M = set_prop (M, "NoiseVariance", v, fname);
    case "method"
      M.Report.Method = check_string (v, name, fname);
      if (! isempty (v))
        M.Report.Status = sprintf ("Estimated using %s", upper (v));
      endif
    case "iterations"
      if (! isnumeric (v) || ! isreal (v) || ! isscalar (v) || ! isfinite (v)
          || v < 0 || v != fix (v))
        error ([fname ":badInput"], ...
               "%s: iterations must be a non-negative integer", fname);
      endif
      M.Report.Termination.Iterations = double (v);
    case "converged"
      if (! (islogical (v) || isnumeric (v)) || ! isscalar (v)
          || ! any (v == [0 1]))
        error ([fname ":badInput"], "%s: converged must be true or false",
               fname);
      endif
      M.Report.Termination.Converged = logical (v);
    case "InterSample"
      M.Report.DataUsed.InterSample = check_string (v, name, fname);
    case "nk"
      M = set_nk (M, v, fname);
    case "theta"
      M = set_theta (M, v, fname);
    case "covariance"
      M = set_covariance (M, v, fname);
    case "NoiseVariance"
      if (! isnumeric (v) || ! isreal (v) || ! isequal (size (v), [M.ny M.ny])
          || any (! isfinite (v(:))) || any (diag (v) < 0))
        error ([fname ":badInput"],
               "%s: NoiseVariance must be a %d-by-%d matrix, diagonal >= 0",
               fname, M.ny, M.ny);
      endif
      M.NoiseVariance = double (v);
    otherwise
      M.par = set_own (M, name, v, fname);
  endswitch
  if (numel (pvec_of (M)) != np_before)
    M.cov = [];
    M.legacy.theta = [];
    M.legacy.covariance = [];
  endif
endfunction

function p = set_own (M, name, v, fname)
  p = M.par;
  switch (M.kind)
    case "idpoly"
      switch (name)
        case {"A", "C", "D"}
          p.(name) = monic_row (v, name, fname, true);
        case {"B", "F"}
          c = poly_cells (v, M.nu, name, fname);
          if (name == "F")
            for j = 1:numel (c)
              c{j} = monic_row (c{j}, "F", fname, false);
            endfor
          endif
          p.(name) = c;
        case "IODelay"
          p.IODelay = check_delay (v, [1, M.nu], "IODelay", fname, M.Ts);
      endswitch
    case "idtf"
      switch (name)
        case {"Numerator", "Denominator"}
          if (! iscell (v))
            v = {v};
          endif
          if (! isequal (size (v), [M.ny, M.nu]))
            error ([fname ":dimensionMismatch"],
                   "%s: %s must be a %d-by-%d cell", fname, name, M.ny, M.nu);
          endif
          for k = 1:numel (v)
            v{k} = real_row (v{k}, name, fname);
            if (name(1) == "D")
              v{k} = monic_row (v{k}, "Denominator", fname, false);
            endif
          endfor
          p.(name) = v;
        case "IODelay"
          p.IODelay = check_delay (v, [M.ny, M.nu], "IODelay", fname, M.Ts);
      endswitch
    case "idproc"
      if (strcmp (name, "Structure"))
        p.Structure = check_structure (v, p.Structure, fname);
      elseif (isfield (p.Structure, name))
        if (! isnumeric (v) || ! isreal (v) || ! isscalar (v))
          error ([fname ":badInput"], "%s: %s must be a real scalar",
                 fname, name);
        endif
        s = p.Structure;
        s.(name).Value = double (v);
        p.Structure = check_structure (s, p.Structure, fname);
      else
        error ([fname ":badInput"], "%s: a %s model has no parameter %s",
               fname, p.Type, name);
      endif
    case "idss"
      switch (name)
        case {"A", "B", "C", "D", "K", "x0"}
          if (! isnumeric (v) || ! isreal (v) || ndims (v) > 2
              || any (! isfinite (v(:))))
            error ([fname ":badInput"], "%s: %s must be a finite real matrix",
                   fname, name);
          endif
          p.(name) = double (v);
          n = rows (p.A);
          if (columns (p.A) != n || rows (p.B) != n || columns (p.C) != n
              || ! isequal (size (p.D), [rows(p.C), columns(p.B)])
              || ! isequal (size (p.B, 2), M.nu) || rows (p.C) != M.ny
              || ! any (numel (p.x0) == [0 n]))
            error ([fname ":dimensionMismatch"],
                   "%s: A, B, C, D do not fit together after setting %s",
                   fname, name);
          endif
        otherwise                       # StateName, StateUnit
          if (ischar (v))
            v = {v};
          endif
          if (! iscellstr (v) || numel (v) != rows (p.A))
            error ([fname ":badInput"], "%s: %s must be %d string(s)",
                   fname, name, rows (p.A));
          endif
          p.(name) = v(:);
      endswitch
    case "idfrd"
      switch (name)
        case "ResponseData"
          if (! isnumeric (v) || size (v, 3) != numel (p.Frequency))
            error ([fname ":dimensionMismatch"],
                   "%s: ResponseData must be ny-by-nu-by-%d", fname,
                   numel (p.Frequency));
          endif
          p.ResponseData = v;
        case "Frequency"
          if (! isnumeric (v) || numel (v) != numel (p.Frequency))
            error ([fname ":dimensionMismatch"],
                   "%s: Frequency must have %d values", fname,
                   numel (p.Frequency));
          endif
          p.Frequency = v(:);
        otherwise
          p.(name) = v;
      endswitch
  endswitch
endfunction

function s = check_string (v, name, fname)
  if (! ischar (v))
    error ([fname ":badInput"], "%s: %s must be a string", fname, name);
  endif
  s = v;
endfunction

function r = merge_report (r, v, fname)
  if (! isstruct (v) || ! isscalar (v))
    error ([fname ":badInput"], "%s: Report must be a scalar struct", fname);
  endif
  for f = fieldnames (v).'
    if (! isfield (r, f{1}))
      error ([fname ":badInput"], "%s: Report has no field '%s'", fname,
             f{1});
    endif
    if (isstruct (r.(f{1})) && isstruct (v.(f{1})))
      for g = fieldnames (v.(f{1})).'
        r.(f{1}).(g{1}) = v.(f{1}).(g{1});
      endfor
    else
      r.(f{1}) = v.(f{1});
    endif
  endfor
endfunction

## CONTSID's nk: input delays in samples of the estimation data.
function M = set_nk (M, v, fname)
  if (! isnumeric (v) || ! isreal (v) || numel (v) != M.nu
      || any (! isfinite (v)) || any (v != fix (v)) || any (v < 0))
    error ([fname ":badInput"], "%s: nk must be one integer >= 0 per input",
           fname);
  endif
  v = double (v(:).');
  Ts = M.Report.DataUsed.Ts;
  if (M.Ts > 0)
    M.InputDelay = v(:);
  elseif (! isempty (Ts))
    M.InputDelay = v(:) * Ts;
  elseif (any (v))
    M.legacy.nk = v;
  endif
endfunction

## CONTSID's theta [denominators, numerators]; a longer theta (a model
## with extra terms, residtrace) is only stored.
function M = set_theta (M, v, fname)
  if (! isnumeric (v) || ! isreal (v) || ! (isvector (v) || isempty (v))
      || any (! isfinite (v)))
    error ([fname ":badInput"], "%s: theta must be a finite real vector",
           fname);
  endif
  T = legacy_order (M);
  if (numel (v) == columns (T))
    ## Parameters outside theta (a noise model) keep their values.
    p = pvec_of (M);
    keep = ! any (T, 2);
    pn = T * double (v(:));
    pn(keep) = p(keep);
    M = pvec_set (M, pn);
    M.legacy.theta = [];
  else
    M.legacy.theta = double (v(:).');
  endif
endfunction

## CONTSID's covariance, in the order of theta: checked as setcov checks
## it (symmetric positive semi-definite).
function M = set_covariance (M, v, fname)
  if (! isempty (v))
    v = check_cov (v, fname);
  endif
  T = legacy_order (M);
  if (rows (v) == columns (T) && isempty (M.legacy.theta))
    M.cov = T * double (v) * T.';
    M.legacy.covariance = [];
  elseif (isempty (v))
    M.cov = [];
    M.legacy.covariance = [];
  else
    M.legacy.covariance = double (v);
  endif
endfunction

function d = check_delay (v, sz, name, fname, Ts)
  if (isscalar (v) && prod (sz) > 1)
    v = repmat (v, sz);
  endif
  if (! isnumeric (v) || ! isreal (v) || numel (v) != prod (sz)
      || any (! isfinite (v(:))))
    error ([fname ":badInput"], "%s: %s must be %d finite value(s)",
           fname, name, prod (sz));
  endif
  if (any (v(:) < 0))
    error ([fname ":badInput"], "%s: %s must be >= 0 (a negative delay)",
           fname, name);
  endif
  if (Ts > 0 && any (v(:) != fix (v(:))))
    error ([fname ":badInput"],
           "%s: a discrete-time %s counts samples (integers)", fname, name);
  endif
  d = reshape (double (v), sz);
endfunction

function r = real_row (v, name, fname)
  if (! isnumeric (v) || ! isreal (v) || (! isvector (v) && ! isempty (v))
      || any (! isfinite (v)))
    error ([fname ":badInput"], "%s: %s must be a finite real row", fname,
           name);
  endif
  r = double (v(:).');
endfunction

function r = monic_row (v, name, fname, allow_empty)
  if (allow_empty && isempty (v))
    v = 1;
  endif
  r = real_row (v, name, fname);
  if (isempty (r) || r(1) != 1)
    error ([fname ":badInput"],
           "%s: %s must be monic (leading coefficient 1), got %s", fname,
           name, mat2str (r, 4));
  endif
endfunction

function c = poly_cells (v, nu, name, fname)
  if (! (iscell (v) || (isnumeric (v) && ismatrix (v))))
    error ([fname ":badInput"],
           "%s: %s must be a row, a matrix with one row per input or a cell",
           fname, name);
  endif
  if (iscell (v))
    c = v(:).';
  elseif (nu > 1 && rows (v) == nu)
    c = num2cell (v, 2).';
  else
    c = {v};
  endif
  if (numel (c) == 1 && nu > 1 && name == "F")
    c = repmat (c, 1, nu);            # one denominator given for all inputs
  endif
  if (numel (c) != nu)
    error ([fname ":dimensionMismatch"],
           "%s: %s needs one polynomial per input (%d), got %d", fname,
           name, nu, numel (c));
  endif
  for j = 1:nu
    c{j} = real_row (c{j}, name, fname);
  endfor
endfunction

function s = check_structure (s, old, fname)
  if (! isstruct (s) || ! isequal (sort (fieldnames (s)),
                                   sort (fieldnames (old))))
    error ([fname ":badInput"],
           "%s: Structure must keep the fields %s", fname,
           strjoin (fieldnames (old)', ", "));
  endif
  for f = fieldnames (s)'
    e = s.(f{1});
    if (! isstruct (e) || ! all (isfield (e, {"Value", "Minimum", "Maximum", ...
                                              "Free"})))
      error ([fname ":badInput"],
             "%s: Structure.%s needs Value, Minimum, Maximum and Free",
             fname, f{1});
    endif
    if (! isnumeric (e.Value) || ! isscalar (e.Value) || ! isreal (e.Value))
      error ([fname ":badInput"],
             "%s: Structure.%s.Value must be a real scalar", fname, f{1});
    endif
    if (isinf (e.Value))
      error ([fname ":badInput"],
             "%s: Structure.%s.Value must be finite (NaN: not yet known)",
             fname, f{1});
    endif
    if (! isnan (e.Value) && (e.Value < e.Minimum || e.Value > e.Maximum))
      error ([fname ":badInput"],
             "%s: %s = %g lies outside [%g, %g]", fname, f{1}, e.Value,
             e.Minimum, e.Maximum);
    endif
    if (strcmp (f{1}, "Td") && e.Value < 0)
      error ([fname ":badInput"], "%s: Td must be >= 0 (a negative delay)",
             fname);
    endif
  endfor
endfunction

## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn  {} {@var{y} =} sim (@var{M}, @var{data})
## @deftypefnx {} {@var{y} =} sim (@var{M}, @var{u})
## Simulates a model (its input-output part, from rest, noise-free) on
## the inputs of @var{data}, an @code{iddata} set (input-only
## @code{iddata ([], u, Ts)} or with outputs; its outputs are ignored).
## Returns, as the System Identification Toolbox, an output-only
## @code{iddata} set of the simulated output with the data's sampling
## interval (or sampling instants) and InterSample, one experiment per
## experiment of @var{data}.  A continuous-time model is simulated by
## @code{simc} (exact for ZOH or FOH inputs, delays included); a
## discrete-time model by its difference equation, which needs the data's
## sampling interval to equal the model's.  Numeric @var{u} (N-by-nu)
## gives a numeric output: for a discrete-time model directly, for a
## continuous-time one @code{sim (M, u, Ts)}.
##
## A continuous-time model that carries levels (@code{srivc} on a raw
## record stores them
## in @code{M.Report.DataUsed.InputOffset} and @code{OutputOffset}; see
## @code{help idpoly}) is simulated by @code{simc} as it was estimated, y = c + M (u - d)
## from rest at those levels, on input data in the record's raw units.
## Option @code{sim (@dots{}, "Levels", "ignore")}: the model alone, as
## MATLAB's @code{sim} (remove the offsets from the data yourself).
##
## @strong{Example}
## @example
## M = idtf (2, [1 1.2 1]);
## M.Report.DataUsed.InputOffset = 5;
## M.Report.DataUsed.OutputOffset = 20;
## u = 5 + ones (100, 1);
## y = sim (M, iddata ([], u, 0.1));          # 20 + step response of 2
## y0 = sim (M, u - 5, 0.1, "Levels", "ignore") + 20;   # the same
## @end example
## @end deftypefn

function varargout = sim (varargin)
  varargout = contsid_guard ({"sim", "idmodel"}, @sim_body, nargout, varargin);
endfunction

function [y, varargout] = sim_body (M, data, varargin)
  contsid_nargchk ("sim", nargin, nargout, [1 Inf], 1);
  P = pstruct (M);
  if (nargin < 2)
    error ([P.kind ":badInput"], "%s: sim needs input data", P.kind);
  endif
  levels = "carried";
  k = find (cellfun (@ischar, varargin), 1);
  if (! isempty (k))
    if (numel (varargin) != k + 1 || ! strcmpi (varargin{k}, "Levels"))
      error ([P.kind ":badOption"],
             "%s: sim takes the one option 'Levels' after M, data[, Ts]",
             P.kind);
    endif
    levels = varargin{k+1};
    varargin = varargin(1:k-1);
  endif
  if (numel (varargin) > 1)
    error ([P.kind ":badInput"], "%s: sim takes M, data[, Ts] and options",
           P.kind);
  endif
  has_ts = ! isempty (varargin);
  if (has_ts)
    Ts = varargin{1};
  endif
  if (strcmp (P.kind, "idfrd"))
    error ("idfrd:notSupported", "idfrd: frequency data cannot be simulated");
  endif
  if (isa (data, "iddata") && strcmpi (data.Domain, "Frequency"))
    y = sim_frequency (M, P, data);
    return;
  endif
  if (isa (data, "iddata"))
    nexp = size (data, 4);
    if (nexp > 1)                      # one simulation per experiment
      ys = cell (1, nexp);
      for k = 1:nexp
        ys{k} = sim (M, getexp (data, k), "Levels", levels);
      endfor
      y = merge (ys{:});
      return;
    endif
    if (has_ts)
      error ([P.kind ":badInput"],
             "%s: sim (M, data) takes no third argument with iddata", P.kind);
    endif
    info = samplinginfo (data);
    if (P.Ts == 0)
      ## The inputs only: the measured outputs (which may have missing
      ## samples) play no part in a simulation.
      yv = ct_sim (M, P, levels, data(:, [], :));
    else
      yv = dt_sim (P, get (data, "InputData"), info.Ts);
    endif
    ## As the SITB: the simulated output only, sampled as the data.
    t = info.Ts;
    if (! info.Uniform)
      t = info.SamplingInstants;
    endif
    y = iddata (yv, [], t, "InterSample", info.InterSample);
    return;
  endif
  if (! isnumeric (data) || ! isreal (data))
    error ([P.kind ":badInput"], "%s: sim needs an iddata set or numeric u",
           P.kind);
  endif
  u = double (data);
  if (isrow (u) && P.nu == 1)
    u = u(:);
  endif
  if (P.Ts == 0)
    if (! has_ts)
      error ([P.kind ":badInput"],
             "%s: a continuous-time model needs sim (M, u, Ts) or iddata",
             P.kind);
    endif
    if (! (isnumeric (Ts) && isreal (Ts) && isscalar (Ts) && Ts > 0
           && isfinite (Ts)))
      error ([P.kind ":badInput"], "%s: sim's Ts must be a finite scalar > 0",
             P.kind);
    endif
    y = ct_sim (M, P, levels, u, Ts);
  else
    y = dt_sim (P, u, P.Ts);
  endif
endfunction

## simc's errors under the model's class and sim's name; simc applies the
## model's levels.
function y = ct_sim (M, P, levels, varargin)
  try
    y = simc (M, varargin{:}, "Levels", levels);
  catch err
    error ([P.kind ":" regexprep(err.identifier, '^.*:', "")], "%s",
           regexprep (err.message, '^simc:', [P.kind ": sim:"]));
  end_try_catch
endfunction

## Difference equation of each input-output pair (z rows of equal length
## read as polynomials in z^-1), delayed by whole samples.
## Frequency-domain input data (as tutorial3's U = fft (u); U.Ts = 0;
## Y = sim (M0, U)): Y(w) = G(jw) U(w) at the data's frequencies, returned
## as output-only frequency-domain data.
function y = sim_frequency (M, P, data)
  U = get (data, "InputData");
  if (iscell (U))
    U = U{1};
  endif
  if (columns (U) != P.nu)
    error ([P.kind ":dimensionMismatch"],
           "%s: the model has %d input(s), the data %d", P.kind, P.nu,
           columns (U));
  endif
  w = data.Frequency(:);
  H = freqresp (M, w);
  Y = zeros (numel (w), P.ny);
  for k = 1:numel (w)
    Y(k, :) = (H(:, :, k) * U(k, :).').';
  endfor
  y = iddata (Y, [], data.Ts, "Frequency", w);
endfunction

function y = dt_sim (P, u, Ts)
  if (! (isscalar (Ts) && abs (Ts - P.Ts) <= 1e-12 * P.Ts))
    error ([P.kind ":badInput"],
           "%s: the data's Ts (%s) differs from the model's (%g)", P.kind,
           merge (isscalar (Ts), num2str (Ts), "irregular"), P.Ts);
  endif
  if (columns (u) != P.nu)
    error ([P.kind ":dimensionMismatch"],
           "%s: the model has %d input(s), the data %d", P.kind, P.nu,
           columns (u));
  endif
  N = rows (u);
  delay = repmat (P.InputDelay(:).', P.ny, 1);
  if (isfield (P.par, "IODelay"))
    delay += P.par.IODelay;
  endif
  y = zeros (N, P.ny);
  if (strcmp (P.kind, "idss"))
    p = P.par;
    x = zeros (rows (p.A), 1);
    for i = 1:P.ny
      ud = shift (u, delay(i, :));
      x(:) = 0;
      for k = 1:N
        y(k, i) = p.C(i, :) * x + p.D(i, :) * ud(k, :).';
        x = p.A * x + p.B * ud(k, :).';
      endfor
    endfor
    return;
  endif
  [num, den] = tf_parts (P);
  for i = 1:P.ny
    for j = 1:P.nu
      n = numel (den{i, j});
      b = [num{i, j}, zeros(1, n - numel (num{i, j}))];
      y(:, i) += filter (b, den{i, j}, shift (u(:, j), delay(i, j)));
    endfor
  endfor
endfunction

function ud = shift (u, d)
  ud = zeros (size (u));
  N = rows (u);
  for j = 1:columns (u)
    ud(d(j)+1:N, j) = u(1:N-d(j), j);
  endfor
endfunction

%!test  # the measured outputs (missing samples included) play no part
%! u = sin ((0:39)' / 4); y = u; y(3) = NaN;
%! M = idtf (1, [1 1]);
%! Y = sim (M, iddata (y, u, 0.1));
%! assert (Y.y, simc (M, u, 0.1), 1e-14);
%!error <no third argument> sim (idtf (1, [1 1]), iddata (ones (9, 1), ones (9, 1), 0.1), 0.1)

%!test  # continuous time: the same as simc; returns iddata
%! Ts = 0.05; u = prbs (7, 4); N = numel (u);
%! M = idtf (2, [1 3 2], "IODelay", 0.1);
%! Y = sim (M, iddata (zeros (N, 0), u, Ts, "InterSample", "foh"));
%! assert (Y.y, simc (M, u, Ts, "InterSample", "foh"), 1e-14);
%! assert (get (Y, "InterSample"), "foh");

%!test  # output-only iddata sampled as the data: 1/(s+1), unit step
%! t = cumsum ([0; 0.05 + 0.1 * rand(29, 1)]);     # irregular instants
%! d = iddata ([], ones (30, 1), "SamplingInstants", t);
%! Y = sim (idtf (1, [1 1]), d);
%! assert (size (Y), [30 1 0 1]);
%! assert (Y.SamplingInstants, t, 1e-15);
%! assert (Y.y, 1 - exp (-t), 1e-12);         # exact ZOH step response
%! Y2 = sim (idtf (1, [1 1]), merge (iddata ([], ones (10, 1), 0.1),
%!                                   iddata ([], ones (20, 1), 0.2)));
%! assert (size (Y2, 4), 2);
%! assert (Y2.y{2}, 1 - exp (-0.2 * (0:19)'), 1e-12);
%! assert ([get(Y2, "Ts"){:}], [0.1 0.2]);

%!test  # frequency-domain input: Y(w) = G(jw) U(w) (tutorial3's form)
%! Ts = 0.05; u = prbs (7, 4);
%! U = fft (iddata ([], u, Ts, "InterSample", "zoh"));
%! U.Ts = 0;
%! M = idtf (2, [1 3 2]);
%! Y = sim (M, U);
%! w = U.Frequency(:);
%! G = 2 ./ ((1i * w) .^ 2 + 3 * 1i * w + 2);
%! assert (Y.y, G .* U.u, 1e-12 * max (abs (U.u)));
%! assert (Y.Frequency(:), w);

%!test  # discrete time against the difference equation
%! u = randn (50, 1);
%! M = idpoly (1, [0 0.5], 1, 1, [1 -0.9], 1, 0.1, "InputDelay", 2);
%! y = sim (M, u);
%! assert (y, filter ([0 0 0 0.5], [1 -0.9], u), 1e-13);
%! S = idss (0.9, 1, 0.5, 0, [], [], 0.1);
%! assert (sim (S, u), filter ([0 0.5], [1 -0.9], u), 1e-13);

%!test  # the levels of a continuous-time model (help idpoly); 'ignore'
%! M = idtf (2, [1 1.2 1]);
%! M.Report.DataUsed.InputOffset = 5;
%! M.Report.DataUsed.OutputOffset = 20;
%! u = 5 + prbs (6, 3); Ts = 0.1;
%! y0 = simc (idtf (2, [1 1.2 1]), u - 5, Ts);
%! Y = sim (M, iddata ([], u, Ts));
%! assert (Y.y, 20 + y0, 1e-12);
%! assert (sim (M, u, Ts), 20 + y0, 1e-12);
%! assert (sim (M, u - 5, Ts, "Levels", "ignore"), y0, 0);
%!error id=idtf:badOption sim (idtf (1, [1 1]), ones (5, 1), 0.1, "Levels", "raw")
%!error id=idtf:badOption sim (idtf (1, [1 1]), ones (5, 1), 0.1, "bogus", 1)
%!error id=idtf:badInput sim (idtf (1, [1 1]), ones (5, 1), [0.1 0.2])
%!error id=idtf:badInput sim (idtf (1, [1 1]))
%!error id=idtf:badInput sim (idtf (1, [1 1]), ones (5, 1))
%!error id=idtf:badInput sim (idtf (1, [1 1]), "u")
%!error id=idtf:badInput sim (idtf (1, [1 1]), [1; NaN; 1], 0.1)
%!error id=idpoly:badInput sim (idpoly (1, 1, 1, 1, [1 -0.5], 1, 0.1), iddata (zeros (5, 0), ones (5, 1), 0.2))
%!error id=idpoly:dimensionMismatch sim (idpoly (1, 1, 1, 1, [1 -0.5], 1, 0.1), ones (5, 2))
%!error id=idfrd:notSupported sim (idfrd (1, 1), ones (5, 1))
%!error id=idpoly:badInput
%! sim (idpoly (1, 1, 1, 1, [1 -0.5], 1, 0.1),
%!      iddata ([], ones (3, 1), "SamplingInstants", [0; 0.1; 0.3]))

%!demo
%! Ts = 0.05; u = prbs (7, 4);
%! Y = sim (idtf (2, [1 3 2]), iddata (zeros (numel (u), 0), u, Ts));
%! plot (Y.y);

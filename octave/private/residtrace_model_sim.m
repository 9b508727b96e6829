## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {[@var{yh}, @var{e}, @var{rmse}, @var{npre}] =} residtrace_model_sim (@var{fname}, @var{m}, @var{d})
## The one simulation of a model @code{residtrace} returns (the struct
## behind an @code{idtraced}), as @code{residtrace} simulated it to score
## it; @code{residtrace_sim}, @code{simc}, @code{sim} and @code{comparec}
## of an @code{idtraced} all come here. Errors carry the identifiers of
## @var{fname}.
##
## @var{d}: the record, fields @code{y} (N-by-1, or empty for an input
## alone), @code{u} (N-by-nu, the record's raw units), @code{Ts},
## @code{intersample} and @code{missing} (the mask of bridged samples,
## @code{residtrace_bridge}).
##
## @itemize
## @item The input level @code{m.u0} is subtracted from the input and the
## model simulated from rest (@code{residtrace_simulate}: its output level
## is one of its output terms). Drift and a noise model are left out:
## they use the measured output.
## @item With an output (a record not used to fit the model), what
## @code{residtrace_valerror} fits on such a record is fitted: the free
## response of an initial state when the model has one
## (@code{m.x0}), the amplitudes of a sinusoid on each half applied to
## the other. When @code{m.npre} > 0 (the model was scored on the last
## part of a split record) and the record is longer, the simulation starts
## at its first sample and @var{e}, @var{rmse} are over samples npre+1
## onward (@var{npre} returned), @var{yh} over all.
## @item Without an output, the model is simulated from the input alone:
## from rest, a sinusoid with the amplitudes fitted on the estimation
## record (time from the first sample); @var{e} is empty, @var{rmse} NaN.
## @end itemize
## A model found in closed loop is @code{@var{fname}:notSupported}.
## @end deftypefn

function [yh, e, rmse, npre] = residtrace_model_sim (fname, m, d)
  need = {"u0", "Ts", "npre", "substeps", "closed_loop", "F", ...
          "channels", "out"};
  if (! isstruct (m) || ! isscalar (m) || ! all (isfield (m, need))
      || ! isnumeric (m.Ts) || ! isscalar (m.Ts) || ! (m.Ts > 0)
      || ! isnumeric (m.u0) || ! isnumeric (m.npre) || ! isscalar (m.npre))
    error ([fname ":badInput"],
           "%s: the model is not one residtrace returned", fname);
  endif
  if (m.closed_loop)
    error ([fname ":notSupported"], "%s: a model found in closed loop",
           fname);
  endif
  nu = numel (m.u0);
  if (columns (d.u) != nu)
    error ([fname ":dimensionMismatch"],
           "%s: the model has %d input(s), the data %d", fname, nu,
           columns (d.u));
  endif
  if (! (abs (d.Ts - m.Ts) <= 1e-9 * m.Ts))
    error ([fname ":badInput"],
           "%s: the data's sampling interval %g is not the model's %g",
           fname, d.Ts, m.Ts);
  endif
  ## the simulated model: drift and a noise model use the measured output
  m.ltv = [];
  m.noise = [];
  N = rows (d.u);
  u = d.u - m.u0(:).';
  npre = 0;
  e = [];
  rmse = NaN;
  try
    if (isempty (d.y))
      yh = residtrace_simulate (m, u, d.Ts, [], m.substeps);
      return;
    endif
    z = zeros (N, 1);
    V = struct ("y", d.y, "u", u, "Ts", d.Ts, "intersample", d.intersample,
                "loop", [], "vhat", [z z], "ysm", d.y, "pre", [],
                "missing", d.missing);
    if (m.npre > 0 && N > m.npre)
      npre = m.npre;
      k = 1:npre;
      V.pre = struct ("y", d.y(k), "u", u(k, :), "vhat", [z(k) z(k)],
                      "ysm", d.y(k));
      k = npre+1:N;
      V.y = d.y(k); V.u = u(k, :); V.vhat = [z(k) z(k)]; V.ysm = d.y(k);
      V.missing = d.missing(k);
    endif
    ctx = struct ("opts", struct ("substeps", m.substeps));
    [e, yv] = residtrace_valerror (m, V, ctx);
    if (npre > 0)
      y0 = residtrace_simulate (m, u(1:npre, :), d.Ts, [], m.substeps);
      yh = [y0; yv];
    else
      yh = yv;
    endif
  catch err
    id = regexprep (err.identifier, '^residtrace:', [fname ':']);
    if (! strncmp (id, [fname ':'], numel (fname) + 1))
      id = [fname ":badInput"];       # not a model residtrace returned
    endif
    error (struct ("identifier", id, "message",
                   [fname ": " regexprep(err.message,
                                         '^residtrace[_a-z]*: ', '')]));
  end_try_catch
  rmse = sqrt (sum (e .^ 2) / max (nnz (! V.missing), 1));
endfunction

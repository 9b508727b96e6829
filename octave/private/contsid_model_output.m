## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {[@var{d}, @var{yhat}, @var{rest}] =} contsid_model_output (@var{fname}, @var{args})
## Shared by comparec and residc: reads the data and a model and simulates
## the model on the data's input from rest.  The model is anything
## @code{contsid_model} reads (idpoly, idtf, idproc, idss, idctm, struct
## with B and F, control tf/ss), simulated by @code{simc}, or a recursive
## estimate THM with its nn (and "order", "bf" for rsrivc's [b f]),
## simulated as the frozen model of each sample, or a model
## @code{residtrace} returned (@code{idtraced}), simulated on the record
## as @code{residtrace} scored it (@code{residtrace_model_sim}).  The data are an iddata
## set (any number of outputs; one experiment) or numeric y, u, Ts.
## The option @code{"Levels"} (@qcode{"carried"}, the default, or
## @qcode{"ignore"}) is read here and passed on to @code{simc}: a model
## that carries levels is simulated with them (doc/manual/levels.md).
## Returns the data struct (y N-by-ny, u, t, Ts, uniform, intersample),
## the simulated output (N-by-ny) and the remaining arguments.
## @end deftypefn

function [d, yhat, rest] = contsid_model_output (fname, args)
  if (numel (args) < 2)
    error ([fname ":badInput"], "%s: expected data and a model", fname);
  endif
  d = read_data (fname, args);
  if (numel (args) <= d.nconsumed)
    error ([fname ":badInput"], "%s: expected a model after the data",
           fname);
  endif
  M = args{d.nconsumed + 1};
  rest = args(d.nconsumed + 2:end);
  levels = "carried";
  k = find (cellfun (@(a) ischar (a) && strcmpi (a, "Levels"), rest), 1);
  if (! isempty (k))
    if (k == numel (rest))
      error ([fname ":badOption"], "%s: Levels needs a value", fname);
    endif
    levels = rest{k+1};
    rest(k:k+1) = [];
    contsid_carried_levels ([], 0, fname, levels);   # checks the value
  endif
  t = merge (d.uniform, d.Ts, d.t);
  try
    if (isnumeric (M))
      if (isempty (rest) || ! isnumeric (rest{1}))
        error ([fname ":badInput"], ...
               "%s: a recursive estimate THM needs its nn", fname);
      endif
      nn = rest{1};
      rest = rest(2:end);
      k = find (cellfun (@(a) ischar (a) && strcmpi (a, "order"), rest), 1);
      if (! isempty (k) && k < numel (rest) && strcmpi (rest{k+1}, "bf"))
        nb = nn(1); na = nn(2);
        nn(1:2) = [na nb];
        M = M(:, [nb+1:end, 1:nb]);
        rest(k:k+1) = [];
      endif
      if (rows (M) != rows (d.y))
        error ([fname ":dimensionMismatch"], ...
               "%s: THM must have one row per sample (%d)", fname, rows (d.y));
      endif
      yhat = simc (M, nn, d.u, t, "InterSample", d.intersample);
    elseif (isa (M, "idtraced"))
      yhat = traced_output (fname, M, d, levels);
    elseif (isobject (M) || isstruct (M))
      yhat = simc (M, d.u, t, "InterSample", d.intersample,
                   "Levels", levels);
    else
      error ([fname ":badInput"], ...
             ["%s: the model must be an idpoly, idtf, idproc, idss (or ", ...
              "idctm), a struct with B and F, a tf/ss, or THM with nn"],
             fname);
    endif
  catch err
    if (strncmp (err.identifier, "simc:", 5))
      id = strrep (err.identifier, "simc:", [fname ":"]);
      msg = strrep (err.message, "simc:", [fname ":"]);
      error (struct ("message", msg, "identifier", id));
    endif
    rethrow (err);
  end_try_catch
  if (columns (yhat) != columns (d.y))
    error ([fname ":dimensionMismatch"],
           "%s: the model has %d output(s), the data %d", fname,
           columns (yhat), columns (d.y));
  endif
endfunction

## A model residtrace returned (idtraced): simulated on the record as
## residtrace scored it (residtrace_model_sim: its levels, effects, and
## what it leaves to a record fitted to the measured output).
function yhat = traced_output (fname, M, d, levels)
  if (! strcmpi (levels, "carried"))
    error ([fname ":notSupported"],
           "%s: a residtrace model's levels are part of it (Levels '%s')",
           fname, levels);
  endif
  if (columns (d.y) != 1)
    error ([fname ":dimensionMismatch"],
           "%s: the model has 1 output, the data %d", fname, columns (d.y));
  endif
  rec = struct ("y", d.y, "u", d.u, "Ts", d.Ts, "intersample",
                d.intersample, "missing", false (rows (d.y), 1));
  yhat = residtrace_model_sim (fname, struct (M).model, rec);
endfunction

## Single-output data through contsid_getdata; an iddata set with
## several outputs (state-space models) read here the same way.
function d = read_data (fname, args)
  data = args{1};
  if (isa (data, "iddata"))
    [~, ny, nu, ne] = size (data);
    if (ny > 1 && ne == 1 && nu >= 1)
      info = samplinginfo (data);
      y = get (data, "OutputData");
      u = get (data, "InputData");
      if (iscell (y))
        [y, u] = deal (y{1}, u{1});
      endif
      if (! (info.Ts > 0) && info.Uniform)
        error ([fname ":badInput"], "%s: the data need a sampling interval",
               fname);
      endif
      d = struct ("y", double (y), "u", double (u),
                  "t", info.SamplingInstants(:), "Ts", info.Ts,
                  "uniform", info.Uniform,
                  "intersample", contsid_intersample (double (u), info),
                  "nconsumed", 1);
      if (! d.uniform)
        d.Ts = NaN;
      endif
      return;
    endif
  endif
  d = contsid_getdata (fname, args{:});
endfunction

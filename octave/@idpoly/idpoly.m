## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn  {} {@var{M} =} idpoly (@var{A}, @var{B}, @var{C}, @var{D}, @var{F}, @var{NoiseVariance}, @var{Ts})
## @deftypefnx {} {@var{M} =} idpoly (@var{A}, @var{B}, @dots{}, @var{name}, @var{value}, @dots{})
## @deftypefnx {} {@var{M} =} idpoly (@var{sys})
## Polynomial model with identifiable parameters (System Identification
## Toolbox semantics), continuous time (@var{Ts} = 0) or discrete time:
## @example
## A y(t) = sum_j B_j/F_j u_j(t - delay_j) + C/D e(t)
## @end example
## In continuous time the polynomials are in s (descending powers,
## @code{[1 f1 .. f_nf]} is s^nf + f1 s^(nf-1) + ..); in discrete time in
## q^-1 (ascending powers, leading zeros of B are sample delays).
##
## Positional arguments, all optional after @var{A}: @var{A}, @var{C},
## @var{D}, @var{F} monic (leading coefficient 1; @code{[]} means 1);
## @var{B} a row (one input), a cell array of rows or a matrix with one row
## per input (several inputs); @var{F} likewise, or one row for all inputs;
## @var{NoiseVariance} (default 1); @var{Ts} (default 1, as the SITB;
## 0 for continuous time).  Name-value pairs set any property:
## @code{Ts}, @code{InputDelay} (one per input; seconds in continuous
## time, samples in discrete time), @code{IODelay}, @code{NoiseVariance},
## @code{InputName}, @code{OutputName}, @code{Name}, @dots{}
##
## @var{sys} converts an @code{idtf}, @code{idproc}, @code{idss} or a
## control-package @code{tf}/@code{ss} (single output) to B/F form.
##
## Properties (@code{M.B}, @code{get (M)}): A, B, C, D, F, IODelay,
## Variable, Ts, InputDelay, NoiseVariance, Report (Report.Fit.FitPercent,
## LossFcn, MSE; Report.Parameters.ParVector, FreeParCovariance), names
## and units; read-only CONTSID aliases @code{theta} ([f b], the idctm
## order), @code{covariance}, @code{nk}, @code{noise_variance},
## @code{method}, @code{iterations}, @code{converged},
## @code{InterSample}.  Methods: @code{sim}, @code{step},
## @code{impulse}, @code{bode} (with @code{'sd'} bands), @code{nyquist},
## @code{pzmap}, @code{zpplot}, @code{pole}, @code{zero}, @code{damp},
## @code{c2d}, @code{d2c}, @code{tf}, @code{ss}, @code{present},
## @code{getpvec}, @code{setpvec}, @code{getcov}, @code{polydata},
## @code{tfdata}, @code{get}, @code{set}.
##
## @strong{Levels and initial state} (every model class; the toolbox's one
## convention, also in doc/manual/levels.md).  A model carries the
## levels it was estimated with in @code{Report.DataUsed.InputOffset}
## (d, one per input) and @code{OutputOffset} (c, one per output): the
## offsets removed from the data, MATLAB's convention, y - c = M (u - d).
## @code{srivc} (and the estimators sharing its engine) sets them when it
## estimates levels on a raw record; a model built here carries none
## (empty: zero); @code{M.Report.DataUsed.InputOffset = 5} sets them.  A
## model carries no initial state: it is simulated from rest at its
## levels (u = d, y = c); the initial state of a record is estimated on
## that record (@code{"InitialCondition", "e"} of @code{simc} and
## @code{comparec}).  @code{simc}, @code{sim} (continuous time),
## @code{comparec}, @code{residc}, @code{srivcstruc} and @code{residtrace}
## simulate a model at its levels, on data in the record's raw units;
## option @code{"Levels", "ignore"} of @code{simc}, @code{sim},
## @code{comparec} and @code{residc} simulates the model alone (MATLAB's
## @code{sim} and @code{compare}: remove the offsets from the data
## yourself).  @code{step}, @code{impulse}, @code{bode} and the other
## responses describe the dynamics M and do not use the levels;
## @code{present} shows them.  Discrete-time models are simulated by
## @code{sim} without levels.
##
## @strong{Example}
## @example
## M0 = idpoly (1, 2, 1, 1, [1 1.2 2], "Ts", 0);     # 2/(s^2+1.2s+2)
## M1 = idpoly (1, @{1, [1 2]@}, 1, 1, @{[1 1], [1 3 2]@}, 0, 0, ...
##              "InputDelay", [0.1 0.2]);             # two inputs
## @end example
## @seealso{idtf, idproc, idss, idfrd, present, srivc}
## @end deftypefn

function varargout = idpoly (varargin)
  ## The precedence over the control package's models is declared here,
  ## in the constructor itself: Octave ignores it from a subfunction.
  try
    superiorto ("tf", "ss", "frd", "lti");
  catch
  end_try_catch
  varargout = contsid_guard ({"idpoly", "idpoly"}, @idpoly_body, nargout,
                             varargin);
endfunction

function [M, varargout] = idpoly_body (varargin)
  contsid_nargchk ("idpoly", nargin, nargout, [0 Inf], 1);
  if (nargin > 0 && (isobject (varargin{1}) || isstruct (varargin{1})))
    M = convert (varargin{:});
    return;
  endif
  [pos, pairs, Tsp] = ctor_args ("idpoly", varargin, [1 7]);
  [A, B, C, D, F, lambda, Ts] = pos{:};
  if (iscell (B))
    nu = numel (B);
  elseif (isempty (B))
    nu = 0;
  else
    nu = rows (B);
  endif
  ## Ts first: it decides how delays are checked.
  if (! isempty (Tsp))
    Ts = Tsp;
  endif
  if (isempty (Ts))
    Ts = 1;
  endif
  if (isempty (F))
    F = 1;
  endif
  par = struct ("A", 1, "B", {repmat({0}, 1, nu)}, "C", 1, "D", 1,
                "F", {repmat({1}, 1, nu)}, "IODelay", zeros (1, nu));
  M = class (struct (), "idpoly", idmodel ("idpoly", par, 1, nu));
  M = set (M, "Ts", Ts);
  if (nu > 0)
    M = set (M, "B", B, "F", F);
  endif
  M = set (M, "A", A, "C", ifempty (C), "D", ifempty (D));
  if (! isempty (lambda))
    M = set (M, "NoiseVariance", lambda);
  endif
  M = set (M, pairs{:});
endfunction

function v = ifempty (v)
  if (isempty (v))
    v = 1;
  endif
endfunction

function M = convert (sys, varargin)
  if (isa (sys, "idpoly"))
    M = set (sys, varargin{:});
    return;
  elseif (isa (sys, "idmodel") || isa (sys, "lti"))
    [num, den] = tfdata (sys);
    if (isa (sys, "idmodel"))
      Ts = get (sys, "Ts");
      delay = totaldelay (sys);
    else
      Ts = max (get (sys, "tsam"), 0);
      delay = zeros (size (num));
    endif
    if (Ts > 0)
      ## control's tf in z: make both rows the same length, then read them
      ## as polynomials in z^-1.
      for k = 1:numel (num)
        n = max (numel (num{k}), numel (den{k}));
        num{k} = [zeros(1, n - numel (num{k})), num{k}];
        den{k} = [zeros(1, n - numel (den{k})), den{k}];
        first = find (den{k} != 0, 1);
        num{k} = num{k}(first:end);
        den{k} = den{k}(first:end);
      endfor
    endif
  else
    error ("idpoly:badInput", "idpoly: cannot convert a %s", class (sys));
  endif
  if (rows (num) != 1)
    error ("idpoly:notSupported",
           "idpoly: only single-output models convert to idpoly");
  endif
  for k = 1:numel (num)
    g = den{k}(1);
    num{k} = num{k} / g;
    den{k} = den{k} / g;
  endfor
  M = idpoly (1, num, 1, 1, den, 1, Ts, "InputDelay", delay(:).',
              varargin{:});
  if (isa (sys, "idmodel"))
    M = set (M, "NoiseVariance", get (sys, "NoiseVariance"),
             "Name", get (sys, "Name"));
  endif
endfunction

%!test  # the CONTSID forms
%! M0 = idpoly (1, 2, 1, 1, [1 1.2 2], "Ts", 0);
%! assert (M0.Ts, 0);
%! assert (M0.B, 2);
%! assert (M0.F, [1 1.2 2]);
%! m = idpoly (1, [1 2], 1, 1, [1 3 2], 0, 0);
%! assert ({m.Ts, m.NoiseVariance}, {0, 0});
%! Mn = idpoly (1, [1 0.5], 1, 1, [1 -0.9], 0, 0.1);
%! assert (Mn.Ts, 0.1);
%! assert (Mn.Variable, "z^-1");
%! Ms = idpoly ([], [1 2], 1, 1, [1 4 3], "Ts", 0);
%! assert (Ms.A, 1);

%!test  # MISO with per-input delays; B and F as rows per input
%! Ts = 0.05;
%! M = idpoly (1, [1 2; 0 3], 1, 1, [1 3 2; 1 4 4], 0, 0,
%!             "InputDelay", [2 5] * Ts);
%! assert (M.B, {[1 2], [0 3]});
%! assert (M.F{2}, [1 4 4]);
%! assert (M.InputDelay, [0.1; 0.25], 1e-15);
%! M2 = idpoly (1, {[1 2], 3}, 1, 1, {[1 3 2], [1 4 4]}, "Ts", 0);
%! assert (numel (getpvec (M2)), 7);

%!test  # idpoly (M, name, value): the same model with properties set
%! M = idpoly (1, 2, [1 0.5], 1, [1 -0.8], 1, 0.1);
%! M2 = idpoly (M, "Name", "plant");
%! assert ({M2.C, M2.F, M2.Name}, {[1 0.5], [1 -0.8], "plant"});

%!test  # conversion from idtf and from control's tf
%! M = idpoly (idtf (2, [1 3 2]));
%! assert ({M.B, M.F, M.Ts}, {2, [1 3 2], 0});
%! pkg load control
%! M = idpoly (tf (4, [2 2]));
%! assert ({M.B, M.F}, {2, [1 1]});

%!error id=idpoly:badInput idpoly (1, ones (2, 2, 2), 1, 1, 1, "Ts", 0)
%!error id=idpoly:badInput idpoly ()
%!error id=idpoly:badInput idpoly (1, 2, 1, 1, [2 1], "Ts", 0)
%!error id=idpoly:badInput idpoly ([2 1], 2, 1, 1, [1 1], "Ts", 0)
%!error id=idpoly:badInput idpoly (1, 2, 1, 1, [1 1], "Ts", 0, "InputDelay", -1)
%!error id=idpoly:badInput idpoly (1, 2, 1, 1, [1 1], "Ts", 0, "bogus", 1)
%!error id=idpoly:badInput idpoly (1, 2, 1, 1, [1 1], "Ts", -1)
%!error id=idpoly:badInput idpoly (1, 2, 1, 1, [1 1], "Ts")
%!error id=idpoly:badInput idpoly (1, 2, 1, 1, [1 1], 1, 0.1, "InputDelay", 0.5)
%!error id=idpoly:dimensionMismatch idpoly (1, {1, 2}, 1, 1, {[1 1], [1 2], [1 3]}, "Ts", 0)
%!error id=idpoly:badInput idpoly (1, 2, 1, 1, [1 NaN], "Ts", 0)
%!error id=idpoly:badInput idpoly ({1})
%!error id=idpoly:badInput idpoly (1, 2, 3, 4, 5, 6, 7, 8)

%!demo
%! M0 = idpoly (1, 2, 1, 1, [1 1.2 2], "Ts", 0)
%! step (M0);

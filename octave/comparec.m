## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn  {} {} comparec (@var{data}, @var{M})
## @deftypefnx {} {} comparec (@var{data}, @var{M}, @var{INT})
## @deftypefnx {} {} comparec (@var{data}, @var{THM}, @var{nn})
## @deftypefnx {} {[@var{ys}, @var{estInfo}] =} comparec (@dots{})
## Simulated versus measured output of a continuous-time model, as
## CONTSID's comparec.
##
## @var{M}: an @code{idpoly} (from @code{srivc}, @code{lssvf},
## @code{ivsvf}, @code{clsrivc}, or built), @code{idtf}, @code{idproc},
## @code{idss} (several outputs), a struct with @code{B} and @code{F}, or
## a control-package @code{tf}/@code{ss}; delays are included.
## A model @code{residtrace} returned (@code{idtraced}: @code{R.model},
## @code{R.final_model}) is simulated as @code{residtrace} simulated it
## to score it, its levels and effects included and what it leaves to a
## record (an initial state it declares, a sinusoid's amplitude) fitted
## on @var{data} (see @code{help idtraced/sim}): on the validation record
## @code{estInfo.RMSE} is @code{R.rmse_final}, and without outputs the
## plot is residtrace's "after" figure.
## @var{THM} with @var{nn} is a recursive estimate (rows = samples, order
## as @code{rlssvf}; add @code{"order", "bf"} for @code{rsrivc}'s),
## simulated as the frozen model of each sample.  The model is simulated
## on the whole input of @var{data} (an iddata set, input-output, or
## numeric y, u, Ts) from rest, at the levels it carries (as
## @code{simc}: a model @code{srivc} estimated on a raw record is compared
## with the raw record, y = c + M (u - d); see @code{help idpoly});
## @var{INT}, increasing sample indices,
## selects the samples that are compared, returned and plotted (all by
## default).
##
## @var{ys}: the simulated output on @var{INT} (N-by-ny).  @var{estInfo}:
## a struct with, per output k (row vectors, @code{estInfo.RT2(1,k)}):
## @table @code
## @item RT2
## 1 - var(y - ys) / var(y), the coefficient of determination CONTSID
## reports;
## @item Fit
## 100 (1 - ||y - ys|| / ||y - mean(y)||) in %;
## (RT2 and Fit are NaN for an output that is constant on the compared
## samples, with a warning @code{comparec:constantOutput});
## @item MSE
## mean((y - ys)^2);
## @item RMSE
## sqrt(MSE).
## @end table
## Without outputs it plots y and ys against time and prints the figures.
##
## Option @code{"InitialCondition", "e"} (as MATLAB's @code{compare}): the
## model's initial state is estimated on @var{data} (least squares on the
## model's free responses, with the refined-IV engine, over the whole
## record) and its free response added to @var{ys}; @code{estInfo.x0}
## holds it and the printed summary says so.  Default @qcode{"z"}: from
## rest (@code{estInfo.x0} empty).
##
## Option @code{"Levels"}: @qcode{"carried"} (default) or
## @qcode{"ignore"}, MATLAB's @code{compare}: the model alone, without
## the levels it carries (give data with the offsets removed).
##
## @strong{Example}
## @example
## u = prbs (9, 8); Ts = 0.05;
## M0 = idpoly (1, 4, 1, 1, [1 2.4 4], "Ts", 0);
## y = simc (M0, u, Ts) + 0.05 * randn (numel (u), 1);
## [ys, estInfo] = comparec (iddata (y, u, Ts), M0, 1:1000);
## estInfo.RT2
## @end example
## @seealso{residc, simc, srivc}
## @end deftypefn

function varargout = comparec (varargin)
  varargout = contsid_guard ("comparec", @comparec_body, nargout, varargin);
endfunction

function [ys, estInfo, varargout] = comparec_body (varargin)
  contsid_nargchk ("comparec", nargin, nargout, [0 Inf], 2);
  [d, yhat, rest] = contsid_model_output ("comparec", varargin);
  N = rows (d.y);
  idx = 1:N;
  thm = isnumeric (varargin{d.nconsumed + 1});
  if (! isempty (rest) && isnumeric (rest{1}) && thm)
    error ("comparec:badOption", "comparec: unexpected extra arguments");
  endif
  if (! isempty (rest) && isnumeric (rest{1}))
    idx = rest{1};
    rest = rest(2:end);
    if (isempty (idx) || ! isvector (idx) || any (idx != fix (idx))
        || any (idx < 1) || any (idx > N) || any (diff (idx) <= 0))
      error ("comparec:badInput",
             "comparec: INT must be increasing sample indices in 1..%d", N);
    endif
  endif
  x0 = [];
  if (numel (rest) == 2 && ischar (rest{1})
      && strcmpi (rest{1}, "InitialCondition"))
    if (! ischar (rest{2})
        || ! any (strcmpi (rest{2}, {"e", "z", "estimate", "zero"})))
      error ("comparec:badOption",
             "comparec: InitialCondition must be 'e' (estimate) or 'z'");
    endif
    if (thm)
      error ("comparec:badOption", ["comparec: InitialCondition needs an ", ...
                                    "LTI model, not a recursive estimate"]);
    endif
    if (any (strcmpi (rest{2}, {"e", "estimate"})))
      t = merge (d.uniform, d.Ts, d.t);
      M = varargin{d.nconsumed + 1};
      if (isa (M, "idtraced"))
        error ("comparec:notSupported",
               ["comparec: a residtrace model fits the initial state it ", ...
                "declares itself (M.x0); no InitialCondition"]);
      endif
      [yhat, x0] = contsid_initial_state ("comparec", M, d.y, yhat, t);
    endif
    rest = {};
  endif
  if (! isempty (rest))
    error ("comparec:badOption", "comparec: unexpected extra arguments");
  endif
  y = d.y(idx, :);
  yh = yhat(idx, :);
  e = y - yh;
  info.RT2 = 1 - var (e, 1) ./ var (y, 1);
  info.Fit = 100 * (1 - sqrt (sum (e .^ 2))
                     ./ sqrt (sum ((y - mean (y)) .^ 2)));
  flat = var (y, 1) == 0;
  if (any (flat))
    ## Fit and RT2 divide by the output's variation: undefined (they
    ## were -Inf, or NaN on an all-zero output)
    info.RT2(flat) = NaN;
    info.Fit(flat) = NaN;
    warning ("comparec:constantOutput",
             ["comparec: output %s is constant on the compared samples: ", ...
              "Fit and RT2 are undefined (NaN); see MSE"],
             strjoin (arrayfun (@num2str, find (flat), "UniformOutput",
                                false), ", "));
  endif
  info.MSE = mean (e .^ 2);
  info.RMSE = sqrt (info.MSE);
  info.x0 = x0;
  if (nargout > 0)
    ys = yh;
    estInfo = info;
    return;
  endif
  t = d.t(idx);
  ny = columns (y);
  for k = 1:ny
    if (ny > 1)
      subplot (ny, 1, k);
    endif
    plot (t, y(:, k), "k", t, yh(:, k), "r");
    legend ("measured", sprintf ("model (fit %.1f %%)", info.Fit(k)));
    title (sprintf ("output %d: RT2 = %.4f", k, info.RT2(k)));
  endfor
  xlabel ("time (s)");
  printf ("output %d: fit = %.2f %%, RT2 = %.4f, MSE = %.4g\n",
          [1:ny; info.Fit; info.RT2; info.MSE]);
  if (! isempty (x0))
    printf ("initial state estimated: y0^(i)(t0) = %s\n", mat2str (x0', 4));
  endif
endfunction

%!shared u, Ts, x, M
%! u = prbs (8, 6); Ts = 0.05;
%! M = idpoly (1, 4, 1, 1, [1 2.4 4], "Ts", 0);
%! x = simc (M, u, Ts);

%!test  # the true model on noise-free data: perfect fit
%! [yh, info] = comparec (iddata (x, u, Ts), M);
%! assert (yh, x, 1e-12);
%! assert (info.Fit, 100, 1e-8);
%! assert (info.RT2(1, 1), 1, 1e-12);
%! assert (info.MSE < 1e-24);

%!test  # the figures' definitions on a known error, on a sample range
%! y = x + 0.1 * sin ((1:numel (x))');
%! INT = 101:400;
%! [yh, info] = comparec (iddata (y, u, Ts), M, INT);
%! assert (yh, x(INT), 1e-12);
%! e = y(INT) - x(INT);
%! assert (info.MSE, mean (e .^ 2), 1e-14);
%! assert (info.Fit, 100 * (1 - norm (e) / norm (y(INT) - mean (y(INT)))),
%!         1e-10);
%! assert (info.RT2, 1 - var (e) / var (y(INT)), 1e-12);
%! [~, info2] = comparec (y, u, Ts, M, INT);
%! assert (info2, info);

%!test  # a constant output: Fit and RT2 undefined (NaN)
%! warning ("off", "comparec:constantOutput", "local");
%! for c = [0 2]
%!   [~, info] = comparec (iddata (c * ones (numel (u), 1), u, Ts), M);
%!   assert ([info.Fit, info.RT2], [NaN NaN]);
%!   assert (info.MSE, mean ((c - x) .^ 2), 1e-12);
%! endfor
%!warning id=comparec:constantOutput
%! [~, info] = comparec (iddata (zeros (numel (u), 1), u, Ts), M);

%!test  # a recursive estimate (constant rows) equals the LTI model
%! THM = repmat ([2.4 4 4], numel (u), 1);
%! yh = comparec (iddata (x, u, Ts), THM, [2 1 0]);
%! assert (yh, x, 1e-12);
%! yh2 = comparec (iddata (x, u, Ts), THM(:, [3 1 2]), [1 2 0], "order", "bf");
%! assert (yh2, x, 1e-12);

%!test  # a two-output idss: RT2 per output; idctm and struct models
%! A = [-1 0; 1 -2]; B = [1; 0]; C = eye (2); D = [0; 0];
%! Ms = idss (A, B, C, D);
%! Y = simc (Ms, u, Ts);
%! [ys, info] = comparec (iddata (Y, u, Ts), Ms, 1:200);
%! assert (size (info.RT2), [1 2]);
%! assert (info.RT2, [1 1], 1e-12);
%! assert (ys, Y(1:200, :), 1e-12);
%! yh = comparec (iddata (x, u, Ts), idctm (4, [1 2.4 4]));
%! assert (yh, x, 1e-12);

%!test  # InitialCondition 'e': a record that starts away from rest
%! u = prbs (8, 6); Ts = 0.05; N = numel (u);
%! M = idpoly (1, 4, 1, 1, [1 2.4 4], "Ts", 0);
%! t = (0:N-1)' * Ts;
%! a = [0 1; -4 -2.4]; c = [4 0];  # controllable form of 4/(s^2+2.4s+4)
%! x0 = [1; -2];
%! yfree = zeros (N, 1);
%! for k = 1:N
%!   yfree(k) = c * expm (a * t(k)) * x0;
%! endfor
%! y = simc (M, u, Ts) + yfree;
%! [~, iz] = comparec (iddata (y, u, Ts), M);
%! [ye, ie] = comparec (iddata (y, u, Ts), M, "InitialCondition", "e");
%! assert (iz.Fit < 99);
%! assert (isempty (iz.x0));
%! assert (ye, y, 1e-8);
%! assert (ie.Fit, 100, 1e-6);
%! out = evalc ("comparec (iddata (y, u, Ts), M, 'InitialCondition', 'e')");
%! assert (! isempty (strfind (out, "initial state estimated")));

%!test  # a model with levels on a raw record; 'ignore' on offset-free data
%! M2 = M;
%! M2.Report.DataUsed.InputOffset = 5;
%! M2.Report.DataUsed.OutputOffset = 20;
%! [yh, info] = comparec (iddata (x + 20, u + 5, Ts), M2, 1:300);
%! assert (yh, x(1:300) + 20, 1e-12);
%! assert (info.Fit, 100, 1e-8);
%! [yh, info] = comparec (iddata (x, u, Ts), M2, "Levels", "ignore");
%! assert (yh, x, 1e-12);

%!error id=comparec:badOption comparec (iddata (x, u, Ts), M, "Levels", "raw")
%!error id=comparec:badOption comparec (iddata (x, u, Ts), M, "Levels")
%!error id=comparec:badInput comparec (ones (20, 1), ones (20, 1), 0.1)
%!error id=comparec:badOption comparec (iddata (x, u, Ts), M, "InitialCondition", "x")
%!error id=comparec:badInput comparec (iddata (x, u, Ts))
%!error id=comparec:badInput comparec (iddata (x, u, Ts), "model")
%!error id=comparec:badInput comparec (iddata (x, u, Ts), [2.4 4 4])
%!error id=comparec:dimensionMismatch comparec (iddata (x, u, Ts), [2.4 4 4; 2.4 4 4], [2 1 0])
%!error id=comparec:badInput comparec (iddata (x, u, Ts), M, [3 2])
%!error id=comparec:badInput comparec (iddata (x, u, Ts), M, 0:3)
%!error id=comparec:badOption comparec (iddata (x, u, Ts), M, 1:3, "x")
%!error id=comparec:dimensionMismatch comparec (iddata (x, u, Ts), idss (-1, 1, [1; 1], [0; 0]))
%!error id=comparec:notSupported comparec (iddata (x, u, (0:numel (u)-1)'.^1.01 * Ts), idtf (1, [1 1], "IODelay", 0.01))

%!demo
%! u = prbs (9, 8); Ts = 0.05; N = numel (u);
%! M0 = idpoly (1, 4, 1, 1, [1 2.4 4], "Ts", 0);
%! y = simc (M0, u, Ts) + 0.05 * randn (N, 1);
%! [ys, estInfo] = comparec (iddata (y, u, Ts), idtf (4.4, [1 2 4]), 1:500);
%! comparec (iddata (y, u, Ts), idtf (4.4, [1 2 4]), 1:500);

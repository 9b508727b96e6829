## -*- texinfo -*-
## @deftypefn  {} {} comparec (@var{data}, @var{M})
## @deftypefnx {} {} comparec (@var{data}, @var{THM}, @var{nn})
## @deftypefnx {} {[@var{yh}, @var{fit}, @var{RT2}, @var{rmse}] =} comparec (@dots{})
## Simulated versus measured output of a continuous-time model.
##
## @var{M} is a model from @code{lssvf}, @code{ivsvf}, @code{srivc},
## @code{clsrivc} (an @code{idctm}), a struct with @code{B} and @code{F}, or
## a control-package @code{tf}; @var{THM} with @var{nn} is a recursive
## estimate (rows = samples, order as @code{rlssvf}; add @code{"order",
## "bf"} for @code{rsrivc}'s), simulated as the frozen model of each sample.
## The model is simulated on the input of @var{data} (an iddata or numeric
## y, u, Ts) from rest.
##
## Option @code{"InitialCondition", "e"}: the model's initial state is
## estimated on @var{data} (least squares on the free responses, with the
## refined-IV engine) and its free response added to @var{yh}; the
## printed summary says so. Default @qcode{"z"}: from rest.
##
## Outputs: the simulated output @var{yh}; @var{fit} = 100 (1 - ||y - yh|| /
## ||y - mean(y)||) in %; @var{RT2} = 1 - var(y - yh) / var(y) (the
## coefficient of determination used by CONTSID); @var{rmse} the root mean
## square of y - yh. Without outputs it plots y and yh and prints the
## three figures.
##
## @strong{Example}
## @example
## u = prbs (9, 8); Ts = 0.05;
## y = simc (idctm (4, [1 2.4 4]), u, Ts) + 0.05 * randn (numel (u), 1);
## [yh, fit] = comparec (iddata (y, u, Ts), idctm (4, [1 2.4 4]));
## @end example
## @seealso{residc, simc, srivc}
## @end deftypefn

function [yh, fit, rt2, rmse] = comparec (varargin)
  [d, yhat, rest] = contsid_model_output ("comparec", varargin);
  x0 = [];
  if (numel (rest) == 2 && ischar (rest{1})
      && strcmpi (rest{1}, "InitialCondition"))
    ## 'e' (estimate) or 'z' (zero): the free response fitted to y.
    if (! ischar (rest{2}) || ! any (strcmpi (rest{2}, {"e", "z",
                                                         "estimate", "zero"})))
      error ("comparec:badOption",
             "comparec: InitialCondition must be 'e' (estimate) or 'z'");
    endif
    if (any (strcmpi (rest{2}, {"e", "estimate"})))
      t = d.t;
      if (d.uniform)
        t = d.Ts;
      endif
      [yhat, x0] = contsid_initial_state ("comparec", varargin{2}, d.y,
                                          yhat, t);
    endif
    rest = {};
  endif
  if (! isempty (rest))
    error ("comparec:badOption", "comparec: unexpected extra arguments");
  endif
  e = d.y - yhat;
  f = 100 * (1 - norm (e) / norm (d.y - mean (d.y)));
  r = 1 - var (e) / var (d.y);
  m = sqrt (mean (e .^ 2));
  if (nargout > 0)
    yh = yhat; fit = f; rt2 = r; rmse = m;
    return;
  endif
  t = d.t;
  plot (t, d.y, "k", t, yhat, "r");
  legend ("measured", sprintf ("model (fit %.1f %%)", f));
  xlabel ("time (s)");
  printf ("fit = %.2f %%, RT2 = %.4f, RMSE = %.4g\n", f, r, m);
  if (! isempty (x0))
    printf ("initial state estimated: y0^(i)(t0) = %s\n", mat2str (x0', 4));
  endif
endfunction

%!shared u, Ts, x, M
%! u = prbs (8, 6); Ts = 0.05;
%! M = idctm (4, [1 2.4 4]);
%! x = simc (M, u, Ts);

%!test  # the true model on noise-free data: perfect fit
%! [yh, fit, rt2, rmse] = comparec (iddata (x, u, Ts), M);
%! assert (yh, x, 1e-12);
%! assert (fit, 100, 1e-8);
%! assert (rt2, 1, 1e-12);
%! assert (rmse < 1e-12);

%!test  # fit and RT2 definitions on a known error
%! y = x + 0.1;
%! [yh, fit, rt2, rmse] = comparec (iddata (y, u, Ts), M);
%! assert (rmse, 0.1, 1e-12);
%! assert (fit, 100 * (1 - norm (y - x) / norm (y - mean (y))), 1e-10);
%! assert (rt2, 1, 1e-12);   # a constant error has zero variance

%!test  # a recursive estimate (constant rows) equals the LTI model
%! THM = repmat ([2.4 4 4], numel (u), 1);
%! yh = comparec (iddata (x, u, Ts), THM, [2 1 0]);
%! assert (yh, x, 1e-12);
%! yh2 = comparec (iddata (x, u, Ts), THM(:, [3 1 2]), [1 2 0], "order", "bf");
%! assert (yh2, x, 1e-12);

%!error id=comparec:badInput comparec (iddata (x, u, Ts))
%!error id=comparec:badInput comparec (iddata (x, u, Ts), "model")
%!error id=comparec:badInput comparec (iddata (x, u, Ts), [2.4 4 4])
%!error id=comparec:dimensionMismatch comparec (iddata (x, u, Ts), [2.4 4 4; 2.4 4 4], [2 1 0])
%!error id=comparec:badOption comparec (iddata (x, u, Ts), M, 3)

%!demo
%! u = prbs (9, 8); Ts = 0.05; N = numel (u);
%! y = simc (idctm (4, [1 2.4 4]), u, Ts) + 0.05 * randn (N, 1);
%! comparec (iddata (y, u, Ts), idctm (4.4, [1 2 4]));

%!test  # InitialCondition 'e': a record that starts away from rest
%! u = prbs (8, 6); Ts = 0.05; N = numel (u);
%! M = idctm (4, [1 2.4 4]);
%! t = (0:N-1)' * Ts;
%! pkg load control
%! [a, b, c] = ssdata (ss (tf (4, [1 2.4 4])));
%! x0 = [1; -2];
%! yfree = zeros (N, 1);
%! for k = 1:N
%!   yfree(k) = c * expm (a * t(k)) * x0;
%! endfor
%! y = simc (M, u, Ts) + yfree;
%! [yz, fz] = comparec (iddata (y, u, Ts), M);
%! [ye, fe] = comparec (iddata (y, u, Ts), M, "InitialCondition", "e");
%! assert (fz < 99);
%! assert (ye, y, 1e-8);
%! assert (fe, 100, 1e-6);
%! out = evalc ("comparec (iddata (y, u, Ts), M, 'InitialCondition', 'e')");
%! assert (! isempty (strfind (out, "initial state estimated")));

%!error id=comparec:badOption comparec (iddata (x, u, Ts), M, "InitialCondition", "x")

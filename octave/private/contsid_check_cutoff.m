## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {} contsid_check_cutoff (@var{fname}, @var{lambda}, @var{d})
## Warn (identifier @code{@var{fname}:cutoffAboveNyquist}) when the SVF
## cut-off @var{lambda} (rad/s) lies above the Nyquist frequency
## @code{pi/Ts} of the record @var{d} (a struct of
## @code{contsid_getdata}; the median interval of irregular samples).
##
## A warning, not an error: the SVF is discretised exactly for the input
## and by the trapezoidal rule for the output, so a cut-off somewhat above
## @code{pi/Ts} can still work (the thesis' band-pass example runs at 20
## times it, with a condition number of P near 1e12); but the filter then
## passes frequencies the samples do not hold, its output channel rings
## near the Nyquist frequency (trapezoidal pole
## @code{(1 - lambda Ts/2) / (1 + lambda Ts/2)}, near -1) and the regressors
## scale as powers of (bandwidth / lambda): far above @code{pi/Ts} the
## estimates are meaningless.
## @end deftypefn

function contsid_check_cutoff (fname, lambda, d)
  if (d.uniform)
    Ts = d.Ts;
  else
    Ts = median (diff (d.t));
  endif
  if (isfinite (Ts) && Ts > 0 && lambda > pi / Ts)
    warning ([fname ":cutoffAboveNyquist"],
             ["%s: lambda_svf = %g rad/s is above the Nyquist frequency ", ...
              "pi/Ts = %g rad/s: the SVF passes what the samples do not ", ...
              "hold and its regressors may be ill-conditioned; the ", ...
              "estimates can be meaningless"], fname, lambda, pi / Ts);
  endif
endfunction

%!warning id=f:cutoffAboveNyquist
%! contsid_check_cutoff ("f", 100, struct ("uniform", true, "Ts", 0.05));
%!warning id=f:cutoffAboveNyquist
%! contsid_check_cutoff ("f", 100, struct ("uniform", false, "Ts", NaN,
%!                                         "t", [0; 0.05; 0.12; 0.15]));
%!test
%! warning ("error", "f:cutoffAboveNyquist", "local");
%! contsid_check_cutoff ("f", 60, struct ("uniform", true, "Ts", 0.05));

## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{is} =} contsid_intersample (@var{u}, @var{info})
## The inter-sample behaviour of the inputs @var{u} (N-by-nu) of an
## @code{iddata} set whose sampling is @var{info} (from
## @code{samplinginfo}): its InterSample when given or when the sampling
## is regular; for irregularly sampled inputs without a given InterSample,
## CONTSID's rule (@code{simc}'s help: the interpolation is chosen from the
## smoothness of the signal, the test of its Runge-Kutta simulator):
## @qcode{"zoh"} (held) when every change of an input is followed by a
## sample without change (no two consecutive differences both nonzero, a
## piecewise-constant signal), else @qcode{"foh"} (linear between the
## instants). Samples that are NaN (missing) take no part in the test.
## @end deftypefn

function is = contsid_intersample (u, info)
  is = info.InterSample;
  if (info.Uniform || (isfield (info, "InterSampleGiven")
                       && info.InterSampleGiven) || rows (u) < 3)
    return;
  endif
  du = diff (u);
  both = du(1:end-1, :) != 0 & du(2:end, :) != 0 ...
         & isfinite (du(1:end-1, :)) & isfinite (du(2:end, :));
  if (any (both(:)))
    is = "foh";
  else
    is = "zoh";
  endif
endfunction

%!test  # a held (piecewise-constant) signal on irregular instants: zoh
%! t = cumsum ([0; 0.1 + rand(39, 1) / 10]);
%! u = kron ([1; -1; 1; 1; -1; 2; 0; 1], ones (5, 1));
%! info = struct ("Uniform", false, "InterSample", "zoh",
%!                "InterSampleGiven", false);
%! assert (contsid_intersample (u, info), "zoh");
%! ## a smooth signal: foh
%! assert (contsid_intersample (sin (t), info), "foh");
%! ## two columns: one smooth one is enough
%! assert (contsid_intersample ([u, sin(t)], info), "foh");
%! ## changes at consecutive samples (a PRBS of period one sample): foh
%! assert (contsid_intersample ([1; -1; 1; 1; -1], info), "foh");
%! ## missing samples do not count
%! assert (contsid_intersample ([1; 1; NaN; 2; 2; 2], info), "zoh");

%!test  # a given InterSample, or regular sampling, is kept
%! info = struct ("Uniform", false, "InterSample", "zoh",
%!                "InterSampleGiven", true);
%! assert (contsid_intersample (sin ((1:20)'), info), "zoh");
%! info.InterSampleGiven = false;
%! info.Uniform = true;
%! assert (contsid_intersample (sin ((1:20)'), info), "zoh");

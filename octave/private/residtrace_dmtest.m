## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{t} =} residtrace_dmtest (@var{e0}, @var{e1})
## Does the error @var{e1} have a smaller mean square than @var{e0} on the
## same samples? The Diebold-Mariano test on d = e0.^2 - e1.^2: the
## statistic mean(d) / sqrt(S / N) with S the Newey-West (Bartlett)
## long-run variance of d, whose bandwidth follows Andrews' AR(1) plug-in
## rule (1991), so that errors correlated in time are not counted as
## independent samples. One-sided p-value from the normal distribution.
##
## @var{t}: @code{score} = 1 - mean(e1.^2) / mean(e0.^2) (the share of
## the mean square removed), @code{stat}, @code{p}, @code{bandwidth} of
## the DM test, and @code{z}, @code{p_corr} of the encompassing test
## (Harvey, Leybourne and Newbold, J. Bus. Econ. Stat. 16 (1998)
## 254-259): does the correction delta = e0 - e1 explain part of e0? In
## the regression e0 = beta delta + u (no intercept, no means removed: a
## constant correction, i.e. a pure offset, is a correction like any
## other), the t value of beta_hat = sum e0 delta / sum delta^2 with the
## Newey-West variance of the score u delta (same bandwidth rule). Both series' autocorrelations are accounted
## for, so slow residuals do not fake significance, and since the
## variance comes from what is left after the correction, a large effect
## does not hide itself (as it can in the DM variance when the residual
## is periodic). One-sided normal p-value of beta > 0. Computed by the
## core (core/include/ctid/apps/residtrace/statistics.hpp, through
## @code{effect_sim_mex}).
## @end deftypefn

function t = residtrace_dmtest (e0, e1)
  v = effect_sim_mex ("residtrace", "dmtest", e0(:), e1(:), struct ());
  t = struct ("score", v(1), "z", v(5), "p_corr", v(6), "stat", v(2),
              "p", v(3), "bandwidth", v(4));
endfunction

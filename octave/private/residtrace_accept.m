## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {[@var{ok}, @var{why}, @var{tmax}] =} residtrace_accept (@var{c}, @var{cur}, @var{N})
## The one acceptance check every @code{residtrace} candidate passes
## before it is scored: its evidence must be physical, whatever the
## effect.
## @table @asis
## @item Determined
## each term the candidate adds to the current model @var{cur} (a new
## channel: its numerator; a new output term: its coefficients; a
## coefficient of F the model had fixed and the candidate frees) must be
## determined on the estimation data: its Wald statistic z (for one
## coefficient |value| / std; for k coefficients sqrt (theta' C^-1 theta
## / k), e.g. a sinusoid's amplitude whatever its phase) at least 2, the
## standard error well below the value; and the effect as a whole must be
## significant there: the largest z at least 3. Terms whose covariance
## was not computed (a realisation fitted on its simulation error) are
## not judged here.
## @item Active and inactive
## an effect that acts on part of the record (a level reached, a
## direction of motion) must act there and not everywhere: the share of
## the @var{N} estimation samples where it is active
## (@code{evidence.share}: at a saturation's level, the velocity
## positive for a friction) at least max (1 %, 5 samples) and at most
## 1 - that (a level reached on every sample is an offset or a gain,
## not a saturation); and an effect that switches
## (@code{evidence.reversals}: the velocity's sign changes for a
## friction) must switch: a velocity that never reverses makes sign(v) a
## constant, an offset, not a friction (a back-and-forth motion with one
## reversal is enough when each direction holds its share of samples).
## @end table
## @var{ok} false gives the reason @var{why}; @var{tmax} is the largest z
## (NaN when no term could be judged), which the screening uses. The
## check is the core's (core/include/ctid/apps/residtrace/judgement.hpp,
## @code{accept}, through @code{effect_sim_mex}).
## @end deftypefn

function [ok, why, tmax] = residtrace_accept (c, cur, N)
  [ok, why, tmax] = effect_sim_mex ("residtrace", "accept", c, cur,
                                    struct ("n", N));
endfunction

%!function [c, cur] = accept_case (val, sd)
%! ## cur: one input channel b0 (nb 1) over F = [1 f1 f2]; the candidate
%! ## adds a constant channel with the gain val +- sd
%! ch = struct ("type", "input", "col", 1, "param", [], "nb", 1, "nk", 0,
%!              "name", "u1", "B", 2);
%! cur = struct ("F", [1 1.2 1], "fixed", [false false], "channels", ch,
%!               "out", struct ("type", {}, "c", {}, "cstd", {}, "omega", {}),
%!               "theta", [1.2 1 2], "cov", 1e-4 * eye (3), "phys", []);
%! m = cur;
%! m.channels(2) = setfield (setfield (ch, "type", "const"), "name", "offset");
%! m.theta = [1.2 1 2 val];
%! m.cov = blkdiag (1e-4 * eye (3), sd ^ 2);
%! c = struct ("model", m, "evidence", struct ("text", ""));

%!test  # an offset of -37 +- 2e6 is not determined; -37 +- 2 is
%! [c, cur] = accept_case (-37, 2e6);
%! [ok, why] = residtrace_accept (c, cur, 1000);
%! assert (! ok);
%! assert (! isempty (strfind (why, "not determined")));
%! [c, cur] = accept_case (-37, 2);
%! [ok, ~, tmax] = residtrace_accept (c, cur, 1000);
%! assert (ok);
%! assert (tmax, 18.5, 1e-12);

%!test  # determined (z >= 2) but not significant as a whole (z < 3)
%! [c, cur] = accept_case (2.5, 1);
%! [ok, why] = residtrace_accept (c, cur, 1000);
%! assert (! ok);
%! assert (! isempty (strfind (why, "not significant")));

%!test  # a saturation at its level on every sample; on none; on part
%! [c, cur] = accept_case (-37, 2);
%! c.evidence.share = 1;
%! [ok, why] = residtrace_accept (c, cur, 1000);
%! assert (! ok);
%! assert (! isempty (strfind (why, "inactive on none")));
%! c.evidence.share = 0.002;
%! assert (! residtrace_accept (c, cur, 1000));
%! c.evidence.share = 0.3;
%! assert (residtrace_accept (c, cur, 1000));

%!test  # a friction needs velocity reversals
%! [c, cur] = accept_case (-37, 2);
%! c.evidence.share = 0.6;
%! c.evidence.reversals = 0;
%! [ok, why] = residtrace_accept (c, cur, 1000);
%! assert (! ok);
%! assert (! isempty (strfind (why, "changes sign 0 time")));
%! c.evidence.reversals = 1;            # there and back: both directions
%! assert (residtrace_accept (c, cur, 1000));
%! c.evidence.share = 0.999;            # one direction on all but 0.1 %
%! assert (! residtrace_accept (c, cur, 1000));

%!test  # a sinusoid's pair is judged jointly: a phase that puts all of
%! ## the amplitude in one coefficient is determined
%! [~, cur] = accept_case (0, 1);
%! m = cur;
%! m.out(1) = struct ("type", "sinusoid", "c", [0.5 0.001], "cstd", [0.01 0.01],
%!                    "omega", 2);
%! [ok, ~, tmax] = residtrace_accept (struct ("model", m, "evidence",
%!                                            struct ()), cur, 1000);
%! assert (ok);
%! assert (tmax, sqrt ((50 ^ 2 + 0.1 ^ 2) / 2), 1e-9);

%!test  # a realisation fitted on its simulation error: not judged here
%! [c, cur] = accept_case (-37, 2e6);
%! c.model.phys = struct ("kind", "stop");
%! [ok, ~, tmax] = residtrace_accept (c, cur, 1000);
%! assert (ok);
%! assert (isnan (tmax));

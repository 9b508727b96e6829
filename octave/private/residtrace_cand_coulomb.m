## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{c} =} residtrace_cand_coulomb (@var{cur}, @var{ctx})
## Coulomb-friction candidate of @code{residtrace}: the extra regressor
## sign(v) in the filtered linear regression, as the thesis does for the
## throttle (sec. 4.2, eq. 4.17), v the velocity: the SVF derivative of
## the measured output (a first-order model reads the output itself as a
## velocity), filtered forward and backward so that its zero crossings
## are not delayed (@code{ctx.D.vhat}), or the output itself when it is
## a velocity (a variant for models of any order; no differentiation);
## whether the term is determined and the velocity reverses often enough
## is @code{residtrace_accept}'s general check (evidence @code{share},
## the share of samples moving forward, and @code{reversals}). A
## second variant adds a constant
## too (Coulomb levels that differ with the direction: sign(v) and an
## offset). When none of them gives a friction (a gain opposing the
## motion), each is fitted again with v the velocity of the
## model's own output (the current model's simulation on the estimation
## record, then the fitted candidate's, twice), filtered the same way: at
## rest the sign of the measured velocity is the measurement noise's,
## correlated with the equation error (a body that sticks between the
## steps of its input then gets a gain pushing along the motion), while
## the model's velocity is free of it and is the one its simulation
## uses. The BIC on the estimation data chooses among the variants whose
## fitted gain opposes the motion (a friction), among all when none does. A fitted b_s > 0 (F
## being monic, a force along the motion) is not friction: the candidate
## is then reported as not applicable, and so is a sign(v) that the
## input's levels and a constant explain to more than 90 % (R^2; with a
## two-level input through a velocity, sign(v) follows the input): "not
## identifiable from these data". Evidence: the
## correlation of the current residual with the filtered sign(v), the
## fitted gain b_s with its standard deviation, and the friction level
## -b_s / b_u in input units (a force when the input is a force).
## The candidate is built and fitted in the core
## (core/include/ctid/apps/residtrace/candidate_coulomb.hpp,
## coulomb_candidate, through @code{effect_sim_mex}, method "candidate").
## @end deftypefn

function c = residtrace_cand_coulomb (cur, ctx)
  c = effect_sim_mex ("residtrace", "candidate", "coulomb", cur, ctx.D,
                     residtrace_fitopts (ctx));
endfunction

## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {[@var{best}, @var{table}] =} residtrace_select (@var{tmpls}, @var{names}, @var{D}, @var{ctx}, @var{starts})
## Fits each model structure of the cell @var{tmpls} on the estimation
## record (@code{residtrace_fit}) and keeps the one with the smallest BIC
## = N log s2 + np log N (Schwarz): the variant of an effect is chosen on
## the estimation data only. @var{starts}: a cell (one cell of initial
## denominators per template). A template with the field @code{fitted}
## set is a model fitted already (by an estimator of its own, e.g. the
## Hammerstein variant by @code{hsrivc}) and is only compared.
##
## With more than two variants they are screened first: each is fitted
## with three SRIVC iterations (one when the caller allows only three,
## i.e. while residtrace screens candidates) from its starts (every start
## is the
## current model, extended, so the first iterations carry most of the
## loss reduction), and only the two with the smallest screening BIC are
## iterated to convergence, each from its screening estimate (the
## variants' loss differences are decided long before their iterations
## end; for speed). @var{table}: the variants' names with their
## BIC and residual variance (after screening, or converged), and
## @code{converged} (iterated to the end). A template with the field
## @code{order_floor_} fails when its fit comes back with a lower order
## (the poles it adds residualised by @code{residtrace_fit}: it is then
## another variant).
## The choice runs in the core
## (core/include/ctid/apps/residtrace/candidate.hpp, select_variant,
## through @code{effect_sim_mex}, method "select"); @var{best} is [] when
## no variant converged.
## @end deftypefn

function [best, table] = residtrace_select (tmpls, names, D, ctx, starts)
  [best, table] = effect_sim_mex ("residtrace", "select", tmpls, names, D,
                                  residtrace_fitopts (ctx, starts));
endfunction

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
## @end deftypefn

function [best, table] = residtrace_select (tmpls, names, D, ctx, starts)
  best = [];
  n = numel (tmpls);
  table = struct ("variant", names, "bic", NaN, "s2", NaN,
                  "converged", false);
  keep = 2;
  screen = n > keep;
  quick = ctx;
  if (screen)
    quick.maxiter = max (1, min (3, floor (ctx.maxiter / 3)));
  endif
  ## the least order a variant's fit may come back with (a template's
  ## field order_floor_): a fit that residualised the poles the variant
  ## adds (residtrace_fit) is another variant, and fails as this one
  lo = zeros (1, n);
  for i = 1:n
    if (isfield (tmpls{i}, "order_floor_"))
      lo(i) = tmpls{i}.order_floor_;
      tmpls{i} = rmfield (tmpls{i}, "order_floor_");
    endif
  endfor
  fits = cell (1, n);
  for i = 1:n
    if (isfield (tmpls{i}, "fitted"))
      m = rmfield (tmpls{i}, "fitted");
      table(i).converged = true;
    else
      m = residtrace_fit (tmpls{i}, D, quick, starts{i});
      table(i).converged = ! screen;
    endif
    m.ok = m.ok && numel (m.F) - 1 >= lo(i);
    fits{i} = m;
    if (m.ok)
      table(i).bic = m.bic;
      table(i).s2 = m.s2;
    endif
  endfor
  if (screen)
    b = [table.bic];
    b(isnan (b)) = Inf;
    [~, order] = sort (b);
    for i = order(1:keep)
      if (! isfinite (b(i)) || table(i).converged)
        continue;
      endif
      ## iterated to convergence from the screening estimate (its F and
      ## numerators), then from the variant's own starts if that fails
      m = residtrace_fit (fits{i}, D, ctx, {fits{i}.F});
      m.ok = m.ok && numel (m.F) - 1 >= lo(i);
      if (! m.ok)
        m = residtrace_fit (tmpls{i}, D, ctx, starts{i});
        m.ok = m.ok && numel (m.F) - 1 >= lo(i);
      endif
      table(i).converged = true;
      if (m.ok)
        fits{i} = m;
        table(i).bic = m.bic;
        table(i).s2 = m.s2;
      else
        table(i).bic = NaN;
      endif
    endfor
  endif
  for i = 1:n
    if (! table(i).converged || ! fits{i}.ok)
      continue;
    endif
    if (isempty (best) || fits{i}.bic < best.bic)
      best = fits{i};
      best.variant_ = names{i};
    endif
  endfor
endfunction

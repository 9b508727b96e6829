## -*- texinfo -*-
## @deftypefn {} {[@var{best}, @var{table}] =} residtrace_select (@var{tmpls}, @var{names}, @var{D}, @var{ctx}, @var{starts})
## Fits each model structure of the cell @var{tmpls} on the estimation
## record (@code{residtrace_fit}) and keeps the one with the smallest BIC
## = N log s2 + np log N (Schwarz): the variant of an effect is chosen on
## the estimation data only. @var{starts}: a cell (one cell of initial
## denominators per template). @var{table}: the variants' names with
## their BIC and residual variance.
## @end deftypefn

function [best, table] = residtrace_select (tmpls, names, D, ctx, starts)
  best = [];
  table = struct ("variant", names, "bic", NaN, "s2", NaN);
  for i = 1:numel (tmpls)
    m = residtrace_fit (tmpls{i}, D, ctx, starts{i});
    if (! m.ok)
      continue;
    endif
    table(i).bic = m.bic;
    table(i).s2 = m.s2;
    if (isempty (best) || m.bic < best.bic)
      best = m;
      best.variant_ = names{i};
    endif
  endfor
endfunction

## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {[@var{W}, @var{o}] =} residtrace_physopts (@var{model}, @var{u}, @var{Ts})
## The arguments of the core's physical realisations
## (@code{effect_sim_mex} methods "physsim" and "physfit",
## @file{core/include/ctid/apps/residtrace/physical_fit.hpp}) for a
## @code{residtrace} model with @code{model.phys}: the channel signals
## @var{W} on the inputs @var{u} (N-by-nu), delayed by each channel's
## nk samples (none for an empty @var{u}), and the realisation's fields
## @var{o} (levels that are not finite and absent fields left out).
## @end deftypefn

function [W, o] = residtrace_physopts (model, u, Ts)
  P = model.phys;
  chans = model.channels;
  N = rows (u);
  if (isempty (u))
    W = zeros (0, numel (chans));
  else
    W = residtrace_channels (chans, u, zeros (N, 1));
  endif
  for j = 1:numel (chans)
    k = chans(j).nk;
    if (k > 0)
      W(:, j) = [zeros(k, 1); W(1:end-k, j)];
    endif
  endfor
  o = struct ("kind", P.kind, "ts", Ts, "substeps", P.substeps);
  if (isfield (P, "yscale"))
    o.yscale = P.yscale;
  endif
  switch (P.kind)
    case "stop"
      n = numel (model.F) - 1;
      m = numel (chans);
      B = zeros (n, m);
      nb = zeros (1, m);
      for j = 1:m
        b = chans(j).B(:);
        nb(j) = numel (b);
        B(n-nb(j)+1:n, j) = b;
      endfor
      o.F = model.F(:).';
      o.fixed = double (model.fixed(:).');
      o.B = B;
      o.nb = nb;
      ## the first output offset is a parameter, the others are fixed
      k = find (strcmp ({model.out.type}, "offset"));
      o.offset_fixed = 0;
      if (! isempty (k))
        o.offset = model.out(k(1)).c(1);
        for i = k(2:end)
          o.offset_fixed += model.out(i).c(1);
        endfor
      endif
      if (isfinite (P.lo))
        o.lo = P.lo;
      endif
      if (isfinite (P.hi))
        o.hi = P.hi;
      endif
    case "cascade"
      o.g = P.g;
      o.b = arrayfun (@(c) c.B(end), chans(:).');
      o.d = P.d; o.alpha = P.alpha; o.gamma = P.gamma; o.c = P.c;
      if (isfield (P, "wbar"))
        o.wbar = P.wbar(:).';
      endif
      if (isfinite (P.hi))
        o.hi = P.hi;
      endif
      for f = {"yhi", "spill", "h0", "z0"}
        if (isfield (P, f{1}) && ! isempty (P.(f{1})))
          o.(f{1}) = P.(f{1});
        endif
      endfor
    otherwise
      error ("residtrace:notSupported", "residtrace: realisation '%s'",
             P.kind);
  endswitch
endfunction

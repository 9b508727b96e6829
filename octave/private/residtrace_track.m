## -*- texinfo -*-
## @deftypefn {} {[@var{thm}, @var{V}, @var{P}] =} residtrace_track (@var{model}, @var{D}, @var{ctx}, @var{Qn}, @var{th0}, @var{P0}, @var{k0})
## Tracks the dynamic parameters of a @code{residtrace} model (its free
## f's, then each channel's numerator) along the record @var{D} by the
## Kalman-filter IV update of the thesis, eq. (2.29):
## @example
## K = P zeta / (1 + phi' P zeta),  theta += K (p^n y_f - phi' theta),
## P = P - K phi' P + Qn
## @end example
## with the prefilter and the auxiliary model frozen at @var{model} (as
## RSRIVC with no refresh; fine for slow drift), regressors phi and
## instruments zeta as in @code{residtrace_srivc}. @var{Qn} is normalised
## by the noise variance, @var{P0} likewise. An update that makes F
## unstable (apart from the model's integrators) is not accepted, as
## the stability test of the thesis' sec. 3.2 with "keep" (P still is).
##
## @var{thm}(k, :) is the estimate after sample k - 1 (one sample behind,
## so that sample k is never explained by itself; before sample @var{k0},
## default 1, the estimate stays at @var{th0}); @var{V} the negative
## log-likelihood of the innovations (prediction-error decomposition, the
## noise variance concentrated out; thesis sec. 3.3), @var{P} the final
## P.
## @end deftypefn

function [thm, V, P] = residtrace_track (model, D, ctx, Qn, th0, P0, k0)
  if (nargin < 7)
    k0 = 1;
  endif
  [lhs, Phi, Z] = regression (model, D, ctx);
  [N, np] = size (Phi);
  free = find (! model.fixed);
  F = model.F;
  n = numel (F) - 1;
  r = 0;
  while (r < n && model.fixed(n-r) && F(n-r+1) == 0)
    r++;
  endwhile
  th = th0(:);
  P = P0;
  thm = zeros (N, np);
  eps2 = zeros (N, 1);
  h = ones (N, 1);
  thm(1:k0-1, :) = repmat (th.', k0 - 1, 1);
  Fk = F;
  nf = numel (free);
  nr = n - r;
  for k = k0:N
    thm(k, :) = th.';
    phi = Phi(k, :).';
    z = Z(k, :).';
    Pz = P * z;
    den = 1 + phi.' * Pz;
    e = lhs(k) - phi.' * th;
    K = Pz / den;
    th_new = th + K * e;
    P += Qn - K * (phi.' * P);
    Fk(1 + free) = th_new(1:nf);
    switch (nr)                         # Hurwitz test of F1 (F = p^r F1)
      case 1
        ok = Fk(2) > 0;
      case 2
        ok = Fk(2) > 0 && Fk(3) > 0;
      case 3
        ok = Fk(2) > 0 && Fk(3) > 0 && Fk(4) > 0 && Fk(2) * Fk(3) > Fk(4);
      otherwise
        ok = residtrace_hurwitz (Fk(1:end-r));
    endswitch
    if (ok)
      th = th_new;
    endif
    eps2(k) = e ^ 2;
    h(k) = abs (den);
  endfor
  skip = min (N - 1, k0 - 1 + max (10, round ((N - k0 + 1) / 50)));
  s2 = mean (eps2(skip+1:end) ./ h(skip+1:end));
  V = (N - skip) * log (s2) + sum (log (h(skip+1:end)));
endfunction

function [lhs, Phi, Z] = regression (model, D, ctx)
  o = 0;
  if (! isempty (model.out))
    [ys, xs] = residtrace_simulate (model, D.u, D.Ts, D.loop,
                                    ctx.opts.substeps);
    o = ys - xs;
  endif
  ch = residtrace_chdata (model, D);
  spec = struct ("n", numel (model.F) - 1, "fixed", model.fixed,
                 "fval", model.F(2:end));
  so = struct ("F0", model.F, "wlo", ctx.wlo);
  [lhs, Phi, Z] = residtrace_srivc (D.y - o, ch, D.Ts, spec, so,
                                    {model.channels.B});
endfunction

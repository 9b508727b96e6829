## -*- texinfo -*-
## @deftypefn {} {@var{c} =} residtrace_cand_coulomb (@var{cur}, @var{ctx})
## Coulomb-friction candidate of @code{residtrace}: the extra regressor
## sign(v) in the filtered linear regression, as the thesis does for the
## throttle (sec. 4.2, eq. 4.17), v the velocity: the SVF derivative of
## the measured output (a first-order model reads the output itself as a
## velocity), filtered forward and backward so that its zero crossings
## are not delayed (@code{ctx.D.vhat}). A second variant adds a constant
## too (Coulomb levels that differ with the direction: sign(v) and an
## offset); the BIC on the estimation data chooses. A fitted b_s > 0 (F
## being monic, a force along the motion) is not friction: the candidate
## is then reported as not applicable. Evidence: the
## correlation of the current residual with the filtered sign(v), the
## fitted gain b_s with its standard deviation, and the friction level
## -b_s / b_u in input units (a force when the input is a force).
## @end deftypefn

function c = residtrace_cand_coulomb (cur, ctx)
  c = residtrace_cand ("coulomb");
  if (any (strcmp ({cur.channels.type}, "signv")))
    c.reason = "the model has Coulomb friction already";
    return;
  endif
  s = sign (ctx.D.vhat);
  if (numel (unique (s(s != 0))) < 2)
    c.reason = "the velocity never changes sign";
    return;
  endif
  vname = "sign(dy/dt)";
  if (numel (cur.F) == 2)
    vname = "sign(y)";
  endif
  t = cur;
  t.channels(end+1) = residtrace_chan ("signv", 0, [], 1, 0, "sign(v)");
  tmpls = {t}; names = {vname}; starts = {{cur.F}};
  if (! any (strcmp ({cur.channels.type}, "const")))
    ## unequal levels for the two directions: sign(v) plus a constant
    t2 = cur;
    t2.channels(end+1) = residtrace_chan ("const", 0, [], 1, 0, "offset");
    t2.channels(end+1) = residtrace_chan ("signv", 0, [], 1, 0, "sign(v)");
    tmpls{end+1} = t2; names{end+1} = [vname ", asymmetric"];
    starts{end+1} = {cur.F};
  endif
  [m, c.variants] = residtrace_select (tmpls, names, ctx.D, ctx, starts);
  if (isempty (m))
    c.reason = "the estimation failed";
    return;
  endif
  k = numel (m.theta);
  val = m.theta(k); sd = sqrt (m.cov(k, k));
  bu = m.channels(1).B(end);
  if (val > 0)                  # F monic: friction needs b_s < 0
    c.reason = sprintf (["the fitted term %.3g sign(v) pushes along ", ...
                         "the motion: not a friction"], val);
    return;
  endif
  c.applicable = true;
  c.model = m;
  c.variant = m.variant_;
  c.nadd = m.np - cur.np;
  Fp = residtrace_prefilter (cur.F, ctx.wlo);
  sf = residtrace_modal (Fp, s, ctx.D.Ts, "zoh")(:, 1);
  r = corr_coef (cur.e_est, sf);
  c.evidence = struct ("term", "b_s (gain of sign(v))", "value", val,
                       "std", sd, "physical", -val / bu,
                       "physical_std", sd / abs (bu), "corr", r,
                       "text", sprintf (["Coulomb level %.4g +- %.2g ", ...
                                         "(input units); corr(residual, ", ...
                                         "sign(v)/F) = %.2f"],
                                        -val / bu, sd / abs (bu), r));
endfunction

function r = corr_coef (a, b)
  a = a - mean (a); b = b - mean (b);
  r = sum (a .* b) / sqrt (sum (a .^ 2) * sum (b .^ 2));
endfunction

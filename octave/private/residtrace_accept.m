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
## (NaN when no term could be judged), which the screening uses.
## @end deftypefn

function [ok, why, tmax] = residtrace_accept (c, cur, N)
  ok = true; why = ""; tmax = NaN;
  m = c.model;
  [z, names] = term_z (m, cur);
  if (! isempty (z))
    tmax = max (z);
    [zmin, i] = min (z);
    if (zmin < 2)
      ok = false;
      why = sprintf (["%s is not determined on the estimation data ", ...
                      "(z = %.2g: its standard error is not well below ", ...
                      "its value)"], names{i}, zmin);
      return;
    endif
    if (tmax < 3)
      ok = false;
      why = sprintf (["the added terms are not significant on the ", ...
                      "estimation data (largest z = %.2g < 3)"], tmax);
      return;
    endif
  endif
  ev = c.evidence;
  if (isstruct (ev) && isfield (ev, "share") && isscalar (ev.share)
      && isfinite (ev.share))
    lo = max (0.01, 5 / N);
    if (ev.share < lo)
      ok = false;
      why = sprintf (["not physically active: active on %.2g %% of the ", ...
                      "estimation samples"], 100 * ev.share);
      return;
    elseif (ev.share > 1 - lo)
      ok = false;
      why = sprintf (["not physically an effect of part of the record: ", ...
                      "active on %.4g %% of the estimation samples, ", ...
                      "inactive on none"], 100 * ev.share);
      return;
    endif
  endif
  if (isstruct (ev) && isfield (ev, "reversals") && ev.reversals < 1)
    ok = false;
    why = sprintf (["not physically active: the velocity changes sign ", ...
                    "%d time(s) on the estimation record (a friction ", ...
                    "needs reversals)"], ev.reversals);
  endif
endfunction

## Wald z of each term the model adds to cur: the channels beyond cur's
## (theta = [free f's, each channel's numerator]) and the output terms
## beyond cur's with a standard deviation.
function [z, names] = term_z (m, cur)
  z = []; names = {};
  if (isempty (m) || ! isstruct (m) || ! isfield (m, "channels")
      || (isfield (m, "phys") && ! isempty (m.phys)))
    return;
  endif
  nc = numel (cur.channels);
  nf = sum (! m.fixed);
  nb = [m.channels.nb];
  if (numel (m.channels) > nc && numel (m.theta) == nf + sum (nb)
      && isequal (size (m.cov), [numel(m.theta), numel(m.theta)]))
    off = nf + sum (nb(1:nc));
    for j = nc+1:numel (m.channels)
      k = off + (1:nb(j));
      off += nb(j);
      zj = wald (m.theta(k), m.cov(k, k));
      if (! isnan (zj))
        z(end+1) = zj;
        names{end+1} = sprintf ("the %s term", m.channels(j).name);
      endif
    endfor
  endif
  ## coefficients of F fixed in cur and freed by the candidate (viscous)
  if (numel (m.fixed) == numel (cur.fixed) && numel (m.theta) >= nf
      && isequal (size (m.cov), [numel(m.theta), numel(m.theta)]))
    freed = find (cur.fixed & ! m.fixed);
    for k = freed
      i = sum (! m.fixed(1:k));
      zk = wald (m.theta(i), m.cov(i, i));
      if (! isnan (zk))
        z(end+1) = zk;
        names{end+1} = sprintf ("the freed coefficient f%d", k);
      endif
    endfor
  endif
  no = numel (cur.out);
  for k = no+1:numel (m.out)
    o = m.out(k);
    if (any (strcmp (o.type, {"sat"})) || numel (o.cstd) != numel (o.c))
      continue;
    endif
    zk = wald (o.c(:), diag (o.cstd(:) .^ 2));
    if (! isnan (zk))
      z(end+1) = zk;
      names{end+1} = sprintf ("the output %s", o.type);
    endif
  endfor
endfunction

## sqrt (theta' C^-1 theta / k); NaN when C gives no standard deviation
function z = wald (th, C)
  th = th(:);
  z = NaN;
  d = diag (C);
  if (isempty (th) || any (! isfinite (C(:))) || any (d <= 0))
    return;
  endif
  s = sqrt (d);
  Cn = C ./ (s * s');                    # correlation: scale-free solve
  [R, p] = chol (Cn);
  if (p != 0)
    return;
  endif
  w = R' \ (th ./ s);
  z = sqrt (sum (w .^ 2) / numel (th));
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

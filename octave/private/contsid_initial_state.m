## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {[@var{yhat}, @var{x0}] =} contsid_initial_state (@var{fname}, @var{M}, @var{y}, @var{yforced}, @var{t})
## The model output with its initial state estimated on measured data (as
## MATLAB's @code{compare (..., 'InitialCondition', 'e')}), for
## @code{comparec} and @code{simc}.
##
## With every coefficient of @var{M} fixed the refined-IV engine
## (@code{contsid_refined_iv}) reduces to a linear least-squares fit of the
## model's free responses (solutions of F(p) y0 = 0, one set per
## denominator) to @var{y} - @var{yforced}, where @var{yforced} is the
## model's response from rest (N-by-1) and @var{t} the sampling interval or
## instants. @var{yhat} = @var{yforced} + y0; @var{x0} holds the initial
## derivatives y0(t0), y0'(t0), .., y0^(nf-1)(t0) of the free response
## (of each denominator in turn when the model has several).
## @var{M}: any single-output continuous-time model
## @code{contsid_model} reads (idpoly, idtf, idproc, struct with B and F,
## control tf).
## @end deftypefn

function [yhat, x0] = contsid_initial_state (fname, M, y, yforced, t)
  m = contsid_model (fname, M);
  if (! strcmp (m.kind, "tf") || m.ny != 1 || m.Ts != 0)
    error ([fname ":badInput"], ["%s: the initial state is estimated for ", ...
                                 "single-output continuous-time transfer ", ...
                                 "function models"], fname);
  endif
  F = m.F(1, :);
  if (m.common)
    F = F(1);
  endif
  ## One free-response set per distinct denominator.
  nf = zeros (1, numel (F));
  theta = [];
  for g = 1:numel (F)
    f = F{g}(:).' / F{g}(1);
    nf(g) = numel (f) - 1;
    theta = [theta; f(2:end).'];
  endfor
  if (any (nf < 1))
    error ([fname ":badInput"],
           "%s: a static model has no initial state to estimate", fname);
  endif
  y = double (y(:));
  n = numel (y);
  resid = y - yforced(:);
  ## The engine needs a channel per denominator: a zero signal with b = 0
  ## fixed, so that only the free responses are fitted.
  ng = numel (nf);
  theta = [theta; zeros(ng, 1)];
  e = struct ("nf", nf, "nb", ones (1, ng), "group", 1:ng,
              "nk", zeros (1, ng), "fixed", true (numel (theta), 1),
              "fixed_values", theta, "theta_init", theta,
              "initial_state", true, "maxiter", 1);
  try
    [~, ~, info] = contsid_refined_iv (fname, resid, zeros (n, ng), t, e);
  catch err
    if (! isempty (strfind (err.message, "stable")))
      error ([fname ":badInput"], ["%s: the initial state can only be ", ...
                                   "estimated for a stable model"], fname);
    endif
    rethrow (err);
  end_try_catch
  yhat = yforced(:) + info.free_response;
  x0 = info.x0;
endfunction

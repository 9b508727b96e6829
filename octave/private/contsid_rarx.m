## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {[@var{thm}, @var{yhat}, @var{thmc}, @var{failed}, @var{P}] =} contsid_rarx (@var{fname}, @var{d}, @var{nn}, @var{o})
## Back-end of @code{rarx} and @code{rarxc}: checks the orders and options
## of the recursive DT ARX estimator and calls its gateway.
##
## @var{d} is the data struct of @code{contsid_getdata}; @var{nn} =
## [na nb nk]; @var{o} a struct with fields @code{adm} (@qcode{"ff"} or
## @qcode{"kf"}), @code{adg}, @code{th0}, @code{P0}, @code{lambda}
## (prefilter cut-off, 0 for none) and @code{continuous} (convert to CT).
## Errors carry the identifier @code{@var{fname}:<reason>}.
## @seealso{rarx, rarxc}
## @end deftypefn

function [thm, yhat, thmc, failed, P] = contsid_rarx (fname, d, nn, o)
  if (columns (d.u) != 1)
    error ([fname ":dimensionMismatch"],
           "%s: the recursive ARX estimator takes one input, got %d",
           fname, columns (d.u));
  endif
  if (! d.uniform)
    error ([fname ":badInput"],
           "%s: the DT ARX model needs uniformly sampled data", fname);
  endif
  if (! (isnumeric (nn) && isreal (nn) && numel (nn) == 3
         && all (isfinite (nn)) && all (nn == fix (nn))))
    error ([fname ":badInput"],
           "%s: nn must be [na nb nk] (three integers)", fname);
  endif
  na = nn(1); nb = nn(2); nk = nn(3);
  if (na < 1 || nb < 1 || nk < 0 || na > 50 || nb > 50)
    error ([fname ":badInput"],
           "%s: nn = [na nb nk] needs 1 <= na, nb <= 50 and nk >= 0", fname);
  endif
  adm = lower (o.adm);
  if (! any (strcmp (adm, {"ff", "kf"})))
    if (any (strcmp (adm, {"ng", "ug"})))
      error ([fname ":notSupported"],
             "%s: adm '%s' (gradient methods) is not supported; use 'ff' or 'kf'",
             fname, adm);
    endif
    error ([fname ":badOption"],
           "%s: adm must be 'ff' or 'kf', got '%s'", fname, adm);
  endif
  np = na + nb;
  contsid_check_input (fname, d.u, nb);
  if (rows (d.y) <= np)
    ## as contsid_recursive_args: more samples than parameters
    error ([fname ":badInput"],
           ["%s: the record has %d samples, fewer than needed for %d ", ...
            "parameters (at least %d)"], fname, rows (d.y), np, np + 1);
  endif
  adg = double (o.adg);
  if (strcmp (adm, "kf") && isscalar (adg))
    adg = adg * eye (np);
  elseif (strcmp (adm, "kf") && isvector (adg) && numel (adg) == np)
    adg = diag (adg);
  endif
  opts = struct ("na", na, "nb", nb, "nk", nk, "Ts", d.Ts, "adm", adm,
                 "adg", adg, "th0", double (o.th0(:)), "P0", double (o.P0),
                 "lambda", double (o.lambda),
                 "continuous", logical (o.continuous));
  [thm, yhat, thmc, failed, P] = rarx_mex (fname, double (d.y),
                                           double (d.u), opts);
endfunction

## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn  {} {@var{nk} =} delayest (@var{data})
## @deftypefnx {} {@var{nk} =} delayest (@var{data}, @var{na}, @var{nb}, @var{nkmin}, @var{nkmax})
## @deftypefnx {} {[@var{nk}, @var{loss}] =} delayest (@dots{})
## Input delay in samples, as the System Identification Toolbox's
## @code{delayest}: least-squares ARX models [@var{na} @var{nb} nk]
## (defaults 2, 2) are fitted for every nk in @var{nkmin}..@var{nkmax}
## (defaults 0 and @var{nkmin} + 20) on the same regression rows, and the
## nk with the smallest loss is returned; @var{loss} holds the losses
## (mean square equation error) for each nk.  The ARX fits are the core's
## (the routine of @code{arx}); one input.
##
## @strong{Example}
## @example
## u = sign (randn (500, 1));
## y = filter ([0 0 0 0.5], [1 -0.8], u) + 0.05 * randn (500, 1);
## nk = delayest (iddata (y, u, 1))          # 3
## @end example
## @seealso{arx, tfsrivc}
## @end deftypefn

function varargout = delayest (varargin)
  varargout = contsid_guard ("delayest", @delayest_body, nargout, varargin);
endfunction

function [nk, loss, varargout] = delayest_body (varargin)
  contsid_nargchk ("delayest", nargin, nargout, [1 6], 2);
  d = contsid_getdata ("delayest", varargin{:});
  contsid_check_output ("delayest", d.y);
  rest = varargin(d.nconsumed+1:end);
  if (size (d.u, 2) != 1)
    error ("delayest:notSupported", "delayest: one input only");
  endif
  if (! d.uniform)
    error ("delayest:badInput", "delayest: needs regularly sampled data");
  endif
  defaults = {2, 2, 0, [], 5};
  for i = 1:numel (rest)
    if (! isempty (rest{i}))
      defaults{i} = rest{i};
    endif
  endfor
  [na, nb, nkmin, nkmax] = defaults{1:4};
  if (isempty (nkmax))
    nkmax = nkmin + 20;
  endif
  ok = @(v) isnumeric (v) && isreal (v) && isscalar (v) && isfinite (v) ...
            && v == fix (v) && v >= 0;
  if (! ok (na) || ! ok (nb) || nb < 1 || ! ok (nkmin) || ! ok (nkmax)
      || nkmax < nkmin)
    error ("delayest:badInput",
           "delayest: na >= 0, nb >= 1, 0 <= nkmin <= nkmax (integers)");
  endif
  n = rows (d.y);
  first = max (na, nkmax + nb - 1);       # common regression rows
  if (n - first <= na + nb)
    error ("delayest:badInput",
           "delayest: too few samples (%d) for nkmax = %d", n, nkmax);
  endif
  cand = nkmin:nkmax;
  loss = zeros (size (cand));
  y = d.y(first-na+1:end);
  for i = 1:numel (cand)
    k = cand(i);
    ## The rows from "first" on for every nk: the record shifted so that the
    ## regression of this nk starts at the same sample.
    s = first - max (na, k + nb - 1);
    [~, ~, info] = pem_mex ("delayest", d.y(s+1:end), d.u(s+1:end, :), 1,
                            struct ("model", "arx", "na", na, "nb", nb,
                                    "nk", k));
    loss(i) = info.loss;
  endfor
  [~, i] = min (loss);
  nk = cand(i);
endfunction

%!test  # the delay of a noisy ARX system is found
%! randn ("state", 1); rand ("state", 1);
%! u = sign (rand (600, 1) - 0.5);
%! y = filter ([0 0 0 0 0.5 0.2], [1 -0.7], u) + 0.05 * randn (600, 1);
%! [nk, loss] = delayest (iddata (y, u, 1));
%! assert (nk, 4);
%! assert (numel (loss), 21);
%! assert (delayest (iddata (y, u, 1), 1, 2, 2, 6), 4);

%!error id=delayest:badInput delayest (iddata ((1:50)', (1:50)', 1), 2, 0)
%!error id=delayest:badInput delayest (iddata ((1:50)', (1:50)', 1), 2, 2, 5, 3)
%!error id=delayest:badInput delayest (iddata ((1:30)', (1:30)', 1), 2, 2, 0, 25)
%!error id=delayest:notSupported delayest (iddata ((1:50)', [(1:50)' (1:50)'], 1))
%!error id=delayest:badInput delayest (1, 2, 3, 4, 5, 6, 7)

%!demo
%! u = sign (randn (500, 1));
%! y = filter ([0 0 0 0.5], [1 -0.8], u) + 0.05 * randn (500, 1);
%! [nk, loss] = delayest (iddata (y, u, 1))

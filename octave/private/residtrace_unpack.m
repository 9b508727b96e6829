## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{model} =} residtrace_unpack (@var{model}, @var{theta})
## Puts the dynamic parameters @var{theta} (free f's, then each channel's
## numerator, the order of the theta of @code{residtrace_fit}) into
## @var{model}.
## @end deftypefn

function model = residtrace_unpack (model, theta)
  free = find (! model.fixed);
  model.F(1 + free) = theta(1:numel (free));
  off = numel (free);
  for j = 1:numel (model.channels)
    nb = model.channels(j).nb;
    model.channels(j).B = theta(off+1:off+nb)(:).';
    off += nb;
  endfor
endfunction

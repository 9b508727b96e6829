## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{ch} =} residtrace_chdata (@var{model}, @var{D})
## The channels of a @code{residtrace} model on the record @var{D} in the
## form of the filtered regression of @code{residtrace_track}: signal (sign of the velocity from
## the measured output @code{D.vhat}, powers of the measured output
## @code{D.ysm}), nb, nk and the hold rule (the
## data's InterSample for the inputs and the signals made from them).
## @end deftypefn

function ch = residtrace_chdata (model, D)
  W = residtrace_channels (model.channels, D.u, D.vhat, D.ysm);
  ch = struct ("w", num2cell (W, 1), "nb", {model.channels.nb},
               "nk", {model.channels.nk}, "rule", D.intersample);
  ch = ch(:);
endfunction

## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{info} =} samplinginfo (@var{dat})
## Sampling of each experiment of the time-domain @code{iddata} set
## @var{dat}.
##
## @var{info} is an @var{e}-by-1 struct array (one element per experiment)
## with fields
## @table @code
## @item Ts
## sampling interval: positive for regular sampling, @code{NaN} for
## irregular sampling, -1 when unspecified (@code{iddata (y, u)}).
## @item SamplingInstants
## @var{N}-by-1 sampling instants: @code{(0:N-1)' * Ts} for regular
## sampling, the stored instants for irregular sampling, the sample indices
## @code{(0:N-1)'} when @code{Ts} is unspecified.
## @item Uniform
## false when the experiment was given a vector of sampling instants.
## @item InterSample
## @qcode{"zoh"}, @qcode{"foh"} or @qcode{"bl"}: the behaviour of the
## inputs between samples.
## @item InterSampleGiven
## true when InterSample was given (set), false for the default
## @qcode{"zoh"}.
## @end table
##
## It reads objects built by this toolbox and by the control package alike;
## the storage is described in @code{help iddata}.  The toolbox's front-ends
## read their data through it.
## @seealso{iddata, get}
## @end deftypefn

function varargout = samplinginfo (varargin)
  varargout = contsid_guard ({"samplinginfo", "iddata"}, @samplinginfo_body,
                             nargout, varargin);
endfunction

function [info, varargout] = samplinginfo_body (dat, varargin)
  contsid_nargchk ("samplinginfo", nargin, nargout, [1 1], 1);
  if (! dat.timedomain)
    error ("iddata:badInput",
           "iddata: samplinginfo: 'dat' is a frequency-domain data set");
  endif
  [~, intersample, given] = unpack_userdata (dat.userdata);
  nexp = numel (dat.y);
  info = struct ("Ts", cell (nexp, 1), "SamplingInstants", [],
                 "Uniform", true, "InterSample", intersample,
                 "InterSampleGiven", given);
  for k = 1:nexp
    n = rows (dat.y{k});
    if (! isempty (dat.w) && ! isempty (dat.w{k}))
      if (numel (dat.w{k}) != n)
        error ("iddata:dimensionMismatch",
               ["iddata: samplinginfo: experiment %d has %d samples but ", ...
                "%d sampling instants"], k, n, numel (dat.w{k}));
      endif
      info(k).Ts = NaN;
      info(k).SamplingInstants = dat.w{k}(:);
      info(k).Uniform = false;
    else
      ts = dat.tsam{k};
      info(k).Ts = ts;
      info(k).SamplingInstants = (0:n-1).' * abs (ts);
    endif
  endfor
endfunction

%!test
%! dat = iddata ((1:5).', (11:15).', 0.5);
%! info = samplinginfo (dat);
%! assert (info.Ts, 0.5);
%! assert (info.SamplingInstants, (0:4).' * 0.5);
%! assert (info.Uniform);
%! assert (info.InterSample, "zoh");

%!test
%! t = [0; 0.1; 0.3; 0.35; 1];
%! dat = iddata (sin (t), cos (t), t, "InterSample", "foh");
%! info = samplinginfo (dat);
%! assert (isnan (info.Ts));
%! assert (info.SamplingInstants, t);
%! assert (! info.Uniform);
%! assert (info.InterSample, "foh");

%!test
%! dat = iddata ({(1:3).', (1:4).'}, {(1:3).', (1:4).'}, {2, -1});
%! info = samplinginfo (dat);
%! assert (size (info), [2, 1]);
%! assert ([info.Ts], [2, -1]);
%! assert (info(1).SamplingInstants, [0; 2; 4]);
%! assert (info(2).SamplingInstants, (0:3).');

%!error id=iddata:badInput
%! samplinginfo (iddata ((1:4).', (1:4).', 1, "Frequency", 0:3));
%!error id=iddata:dimensionMismatch
%! ## a length change that left the instants behind (as control's nkshift
%! ## and diff do)
%! dat = iddata ((1:4).', (1:4).', (0:3).' .^ 2);
%! dat = builtin ("subsasgn", dat, substruct (".", "y"), {(1:3).'});
%! dat = builtin ("subsasgn", dat, substruct (".", "u"), {(1:3).'});
%! samplinginfo (dat);

%!demo
%! t = cumsum (0.1 + 0.05 * rand (50, 1));   # irregular sampling instants
%! data = iddata (sin (t), sign (sin (2 * t)), t, "InterSample", "foh");
%! info = samplinginfo (data)

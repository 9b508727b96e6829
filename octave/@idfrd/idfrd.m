## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn  {} {@var{G} =} idfrd (@var{response}, @var{w}, @var{Ts})
## @deftypefnx {} {@var{G} =} idfrd (@var{response}, @var{w}, @var{name}, @var{value}, @dots{})
## @deftypefnx {} {@var{G} =} idfrd (@var{sys}, @var{w})
## Frequency response data (System Identification Toolbox semantics):
## the complex response @var{response} at the frequencies @var{w} (rad/s,
## @var{N} values), given as an @var{N}-vector (one input, one output) or
## an ny-by-nu-by-@var{N} array.  @var{Ts} = 0 (default; as in
## @code{idfrd (G, w, 'Ts', 0)}) marks a continuous-time system.
## @var{sys} (any model of this toolbox or of the control package) is
## evaluated at @var{w}.
##
## Properties: ResponseData, Frequency, FrequencyUnit (@qcode{"rad/s"}),
## Ts and the common ones.  @code{bode (G)} and @code{nyquist (G)} plot
## the data; methods that need a parametric model raise
## @code{idfrd:notSupported}.
##
## @strong{Example}
## @example
## w = logspace (-1, 1, 50);
## G = idfrd (2 ./ ((1i*w).^2 + 3*1i*w + 2), w, "Ts", 0);
## @end example
## @seealso{idtf, bode, freqresp}
## @end deftypefn

function varargout = idfrd (varargin)
  ## The precedence over the control package's models is declared here,
  ## in the constructor itself: Octave ignores it from a subfunction.
  try
    superiorto ("tf", "ss", "frd", "lti");
  catch
  end_try_catch
  varargout = contsid_guard ({"idfrd", "idfrd"}, @idfrd_body, nargout,
                             varargin);
endfunction

function [G, varargout] = idfrd_body (varargin)
  contsid_nargchk ("idfrd", nargin, nargout, [0 Inf], 1);
  if (nargin < 2)
    if (nargin == 1 && isa (varargin{1}, "idfrd"))
      G = varargin{1};
      return;
    endif
    error ("idfrd:badInput", "idfrd: expected the response and frequencies");
  endif
  [R, w] = deal (varargin{1:2});
  rest = varargin(3:end);
  if (! isempty (rest) && isnumeric (rest{1}))
    rest = [{"Ts"}, rest];
  endif
  if (! isnumeric (w) || ! isreal (w) || ! isvector (w) || any (w < 0)
      || any (! isfinite (w)))
    error ("idfrd:badInput", "idfrd: w must be a vector of frequencies >= 0");
  endif
  w = double (w(:));
  if (isa (R, "idmodel") || isa (R, "lti"))
    R = freqresp (R, w);
  endif
  if (! isnumeric (R) || any (! isfinite (R(:))))
    error ("idfrd:badInput", "idfrd: the response must be finite numbers");
  endif
  if (isvector (R))
    R = reshape (R, 1, 1, []);
  endif
  if (size (R, 3) != numel (w))
    error ("idfrd:dimensionMismatch",
           "idfrd: %d frequencies but %d response values per channel",
           numel (w), size (R, 3));
  endif
  par = struct ("ResponseData", double (R), "Frequency", w,
                "FrequencyUnit", "rad/s");
  G = class (struct (), "idfrd",
             idmodel ("idfrd", par, size (R, 1), size (R, 2)));
  if (mod (numel (rest), 2) != 0)
    error ("idfrd:badInput", "idfrd: properties must come in name-value pairs");
  endif
  G = set (G, rest{:});
endfunction

%!test
%! w = [0.5 1 2];
%! R = 2 ./ ((1i*w).^2 + 3*1i*w + 2);
%! G = idfrd (R, w, "Ts", 0);
%! assert (squeeze (G.ResponseData).', R);
%! assert (G.Frequency, w(:));
%! G2 = idfrd (idtf (2, [1 3 2]), w);
%! assert (G2.ResponseData, G.ResponseData, 1e-14);

%!error id=idfrd:badInput idfrd (1)
%!error id=idfrd:badInput idfrd ([1 2], [-1 1])
%!error id=idfrd:dimensionMismatch idfrd ([1 2 3], [1 2])
%!error id=idfrd:badInput idfrd ([1 2], [1 2], "Ts")
%!error id=idfrd:badInput idfrd ([1 NaN], [1 2])

%!demo
%! w = logspace (-1, 1, 50);
%! G = idfrd (idtf (2, [1 3 2]), w);
%! bode (G);

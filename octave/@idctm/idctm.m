## -*- texinfo -*-
## @deftypefn  {} {@var{M} =} idctm (@var{B}, @var{F})
## @deftypefnx {} {@var{M} =} idctm (@var{B}, @var{F}, @var{name}, @var{value}, @dots{})
## @deftypefnx {} {@var{M} =} idctm (@var{s})
## A continuous-time transfer-function model
## @example
## y = sum_j B_j(p) / F(p) u_j(t - nk_j Ts) (+ e)
## @end example
## as returned by @code{lssvf}, @code{ivsvf}, @code{srivc} and
## @code{clsrivc} (this toolbox's counterpart of CONTSID's idpoly).
##
## @var{B}: numerator coefficients in descending powers of p (a cell array
## of rows for several inputs); @var{F}: denominator [1 f1 .. f_nf]
## (normalised to be monic). Properties (read with @code{M.name}):
## @table @code
## @item B, F, nk
## the model; nk the input delays in samples.
## @item Ts, InterSample
## sampling interval and intersample behaviour of the estimation data.
## @item theta, covariance
## the parameters [f1 .. f_nf, b ..] and their estimated covariance.
## @item noise_variance, method, iterations, converged
## estimation information.
## @end table
## @code{simc}, @code{comparec}, @code{residc} and @code{bode4frozensys}
## accept it; @code{tf (M)} converts it to a control-package @code{tf}
## (with the control package loaded) and @code{struct (M)} to a struct.
##
## @strong{Example}
## @example
## M = idctm (4, [1 2.4 4]);
## y = simc (M, prbs (8, 4), 0.1);
## @end example
## @seealso{srivc, lssvf, simc, comparec}
## @end deftypefn

function M = idctm (varargin)
  fields = {"B", "F", "nk", "Ts", "InterSample", "theta", "covariance", ...
            "noise_variance", "method", "iterations", "converged"};
  if (nargin == 1 && isa (varargin{1}, "idctm"))
    M = varargin{1};
    return;
  endif
  if (nargin == 1 && isstruct (varargin{1}))
    s = varargin{1};
  elseif (nargin >= 2 && mod (nargin, 2) == 0)
    s = struct ("B", {varargin(1)}, "F", varargin{2});
    s.B = varargin{1};
    for i = 3:2:nargin
      if (! ischar (varargin{i}) || ! any (strcmp (varargin{i}, fields)))
        error ("idctm:badOption", "idctm: unknown property '%s'",
               num2str (varargin{i}));
      endif
      s.(varargin{i}) = varargin{i+1};
    endfor
  else
    error ("idctm:badInput", "idctm: expected B and F, or a struct");
  endif
  if (! isfield (s, "B") || ! isfield (s, "F"))
    error ("idctm:badInput", "idctm: the model needs B and F");
  endif
  F = s.F;
  if (! isnumeric (F) || ! isreal (F) || ! isvector (F) || numel (F) < 2
      || F(1) == 0 || any (! isfinite (F)))
    error ("idctm:badInput", "idctm: F must be a finite [1 f1 .. f_nf]");
  endif
  B = s.B;
  if (! iscell (B))
    B = {B};
  endif
  for j = 1:numel (B)
    if (! isnumeric (B{j}) || ! isreal (B{j}) || isempty (B{j})
        || ! isvector (B{j}) || any (! isfinite (B{j})))
      error ("idctm:badInput", "idctm: B must be finite real rows");
    endif
    B{j} = double (B{j}(:).') / F(1);
    if (numel (B{j}) > numel (F))
      error ("idctm:badInput", "idctm: improper model (deg B > deg F)");
    endif
  endfor
  F = double (F(:).') / F(1);
  defaults = struct ("nk", zeros (1, numel (B)), "Ts", [],
                     "InterSample", "zoh", "theta", [], "covariance", [],
                     "noise_variance", [], "method", "", "iterations", 0,
                     "converged", true);
  m = struct ();
  for i = 1:numel (fields)
    f = fields{i};
    if (isfield (s, f))
      m.(f) = s.(f);
    elseif (isfield (defaults, f))
      m.(f) = defaults.(f);
    endif
  endfor
  nk = m.nk;
  if (! isnumeric (nk) || ! isreal (nk) || numel (nk) != numel (B)
      || any (! isfinite (nk(:))) || any (nk(:) < 0)
      || any (nk(:) != fix (nk(:))))
    error ("idctm:badInput",
           "idctm: nk must hold %d finite integer delays >= 0 (one per input)",
           numel (B));
  endif
  m.nk = double (nk(:).');
  m.F = F;
  m.B = B;
  if (numel (B) == 1)
    m.B = B{1};
  endif
  if (isempty (m.theta))
    m.theta = [F(2:end), cell2mat(B)];
  endif
  M = class (m, "idctm");
endfunction

%!test
%! M = idctm (4, [2 4.8 8]);
%! assert (M.F, [1 2.4 4]);
%! assert (M.B, 2);
%! assert (M.theta, [2.4 4 2]);
%! s = struct (M);
%! assert (s.nk, 0);

%!test
%! M = idctm ({1, [1 2]}, [1 3 2], "nk", [0 1], "Ts", 0.1);
%! assert (M.nk, [0 1]);
%! assert (iscell (M.B));

%!error id=idctm:badInput idctm (1)
%!error id=idctm:badInput idctm (1, [0 1])
%!error id=idctm:badInput idctm ([1 2 3], [1 1])
%!error id=idctm:badInput idctm ({"a"}, [1 1])
%!error id=idctm:badOption idctm (1, [1 1], "bogus", 1)
%!error id=idctm:badInput idctm (1, [1 1], "nk", NaN)
%!error id=idctm:badInput idctm (1, [1 1], "nk", -1)
%!error id=idctm:badInput idctm (1, [1 1], "nk", [0 1])

%!demo
%! M = idctm (4, [1 2.4 4])
%! y = simc (M, ones (100, 1), 0.05); plot (y);

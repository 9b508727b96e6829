## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn  {} {[@var{num}, @var{den}] =} tfdata (@var{M})
## @deftypefnx {} {[@var{num}, @var{den}, @var{Ts}] =} tfdata (@var{M}, "v")
## Numerators and denominators of the input-output part of a model, as
## ny-by-nu cells of rows (or rows with @qcode{"v"} for one input and one
## output): descending powers of s in continuous time, of z in discrete
## time (the discrete-time idpoly's q^-1 polynomials padded to equal
## length).  Delays are not included (see @code{totaldelay}).  An
## @code{idproc} with NaN parameters, or an @code{idfrd}: error
## @code{<class>:badInput} / @code{<class>:notSupported}.
## @end deftypefn

function varargout = tfdata (varargin)
  varargout = contsid_guard ({"tfdata", "idmodel"}, @tfdata_body, nargout,
                             varargin);
endfunction

function [num, den, Ts, varargout] = tfdata_body (M, form, varargin)
  contsid_nargchk ("tfdata", nargin, nargout, [1 2], 3);
  P = pstruct (M);
  [num, den] = tf_parts (P);
  Ts = P.Ts;
  if (nargin > 1)
    if (! ischar (form) || ! any (strcmpi (form, {"v", "vector"})))
      error ([P.kind ":badInput"], "%s: tfdata's option must be 'v'", P.kind);
    endif
    if (numel (num) != 1)
      error ([P.kind ":badInput"],
             "%s: tfdata (M, 'v') needs one input and one output", P.kind);
    endif
    num = num{1};
    den = den{1};
  endif
endfunction

%!test
%! [n, d] = tfdata (idpoly (1, 2, 1, 1, [1 1.2 2], "Ts", 0), "v");
%! assert ({n, d}, {2, [1 1.2 2]});
%! [n, d] = tfdata (idpoly (1, [0 0.5], 1, 1, [1 -0.9], 1, 0.1));
%! assert ({n{1}, d{1}}, {[0 0.5], [1 -0.9]});
%! [n, d] = tfdata (idproc ("P1", "Kp", 2, "Tp1", 4));
%! assert ({n{1}, d{1}}, {0.5, [1 0.25]});
%! [n, d] = tfdata (idss (-2, 1, 3, 1), "v");
%! assert ({n, d}, {[1 5], [1 2]}, 1e-14);
%!error id=idproc:badInput tfdata (idproc ("P1"))
%!error id=idfrd:notSupported tfdata (idfrd (1, 1))
%!error id=idpoly:badInput tfdata (idpoly (1, {1, 1}, 1, 1, [1 1], "Ts", 0), "v")

%!demo
%! [num, den] = tfdata (idproc ("P1D", "Kp", 2, "Tp1", 4, "Td", 1), "v")

## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{d} =} totaldelay (@var{M})
## Total delay of each input-output pair of a model (ny-by-nu): input
## delay plus I/O delay (plus Td of a process model); seconds in
## continuous time, samples in discrete time.
## @end deftypefn

function varargout = totaldelay (varargin)
  varargout = contsid_guard ({"totaldelay", "idmodel"}, @totaldelay_body,
                             nargout, varargin);
endfunction

function [d, varargout] = totaldelay_body (M, varargin)
  contsid_nargchk ("totaldelay", nargin, nargout, [1 1], 1);
  M = pstruct (M);
  d = repmat (M.InputDelay(:).', M.ny, 1);
  switch (M.kind)
    case {"idpoly", "idtf"}
      d += M.par.IODelay;
    case "idproc"
      if (isfield (M.par.Structure, "Td"))
        td = M.par.Structure.Td.Value;
        if (isnan (td))
          td = 0;
        endif
        d += td;
      endif
  endswitch
endfunction

%!test
%! assert (totaldelay (idtf (1, [1 1], "IODelay", 0.2, "InputDelay", 0.1)),
%!         0.3, 1e-15);
%! assert (totaldelay (idproc ("P1D", "Td", 2)), 2);
%! M = idpoly (1, {1, 2}, 1, 1, {[1 1], [1 2]}, 0, 0, "InputDelay", [1 2]);
%! assert (totaldelay (M), [1 2]);

%!demo
%! totaldelay (idtf (1, [1 1], "IODelay", 0.2))

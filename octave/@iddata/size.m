## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn  {} {@var{sz} =} size (@var{data})
## @deftypefnx {} {[@var{n}, @var{ny}, @var{nu}, @var{ne}] =} size (@var{data})
## @deftypefnx {} {@var{x} =} size (@var{data}, @var{dim})
## @deftypefnx {} {} size (@var{data})
## Dimensions of an @code{iddata} set, as in MATLAB and the control
## package.
##
## @var{sz} is @code{[N, ny, nu, ne]}: total number of samples, outputs,
## inputs and experiments.  With several outputs, @var{n} is the row of
## the numbers of samples of each experiment.  @var{dim} (1 to 4) picks one
## of @var{n}, @var{ny}, @var{nu}, @var{ne}.  Without an output argument
## the dimensions are printed.
## @seealso{iddata}
## @end deftypefn

function varargout = size (dat, dim, varargin)
  contsid_nargchk ("size", nargin, nargout, [1 2], 4);
  n = cellfun ("rows", dat.y(:).');
  dims = {n, numel(dat.outname), numel(dat.inname), numel(dat.y)};
  if (nargin == 2)
    if (! (isnumeric (dim) && isscalar (dim) && any (dim == 1:4)))
      error ("iddata:badInput", "iddata: size: 'dim' must be 1, 2, 3 or 4");
    endif
    if (nargout > 1)
      error ("iddata:badInput", "iddata: size (dat, dim) has one output");
    endif
    varargout{1} = dims{dim};
  elseif (nargout == 0)
    plural = {"", "s"};
    printf ("iddata set with %s sample%s, %d output%s, %d input%s and ",
            num2str (n), plural{1 + (sum (n) != 1)},
            dims{2}, plural{1 + (dims{2} != 1)},
            dims{3}, plural{1 + (dims{3} != 1)});
    printf ("%d experiment%s\n", dims{4}, plural{1 + (dims{4} != 1)});
  elseif (nargout == 1)
    varargout{1} = [sum(n), dims{2:4}];
  elseif (nargout <= 4)
    varargout = dims(1:nargout);
  else
    error ("iddata:badInput", "iddata: size: at most four outputs");
  endif
endfunction

%!shared data
%! data = iddata ({(1:5).', (1:3).'}, {ones(5, 2), ones(3, 2)}, 1);

%!test
%! assert (size (data), [8, 1, 2, 2]);
%! [n, ny, nu, ne] = size (data);
%! assert ({n, ny, nu, ne}, {[5, 3], 1, 2, 2});
%! assert (size (data, 1), [5, 3]);
%! assert (size (data, 3), 2);

%!error id=iddata:badInput [a, b] = size (iddata (ones (5, 1), ones (5, 1), 1), 1)
%!error id=iddata:badInput size (data, 5)
%!error id=size:badInput [a, b, c, d, e] = size (data);

%!demo
%! size (iddata (randn (100, 1), randn (100, 2), 0.1))

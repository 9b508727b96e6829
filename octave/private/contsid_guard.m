## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{out} =} contsid_guard (@var{fname}, @var{body}, @
##   @var{nout}, @var{args})
## Runs the body @var{body} (a handle) of the public function @var{fname}
## with the arguments @var{args} (a cell) and @var{nout} outputs, returned
## in the cell @var{out}, and re-raises any error under the identifier of
## @var{fname} (see @code{contsid_rethrow}): an error raised by an inner
## call (another toolbox function, the control package, Octave itself)
## then names the function the user called.  A public function is the
## one-line wrapper
## @example
## function varargout = f (varargin)
##   varargout = contsid_guard ("f", @@f_body, nargout, varargin);
## endfunction
## @end example
## followed by its body @code{f_body}, which sees the caller's
## @code{nargin} and @code{nargout}.  Called without outputs, the body's
## first output (when it sets one) becomes @code{ans}, as for a direct
## call.  For a method @var{fname} is a cell @code{@{method, class@}}: the
## identifiers of that class and of the classes of the objects among
## @var{args} (a subclass inheriting the method) are then its own too.
## @end deftypefn

function out = contsid_guard (fname, body, nout, args)
  try
    if (nout == 0)
      body (args{:});
      if (exist ("ans", "var"))
        out = {ans};
      else
        out = {};
      endif
    else
      out = cell (1, nout);
      [out{:}] = body (args{:});
    endif
  catch err
    if (iscell (fname))
      ## a method: its class's and its objects' classes' identifiers are
      ## its own (an inherited method raises them under the subclass)
      obj = args(cellfun ("isobject", args));
      fname = [fname, cellfun(@class, obj, "UniformOutput", false)];
    endif
    contsid_rethrow (err, fname);
  end_try_catch
endfunction

%!test  # outputs as asked; without outputs the first becomes ans
%! out = contsid_guard ("f", @(x) deal (x + 1, x + 2), 2, {1});
%! assert (out, {2, 3});
%! assert (contsid_guard ("f", @(x) x + 1, 0, {1}), {2});
%!error id=f:badInput
%! contsid_guard ("f", @() error ("inner:badInput", "inner: bad"), 1, {});
%!error id=f:indexOutOfBounds contsid_guard ("f", @(x) x(3), 1, {[1 2]});
%!test  # a method keeps its objects' classes' identifiers
%! M = idtf (1, [1 1]);
%! try
%!   contsid_guard ({"m", "idmodel"},
%!                  @(M) error ("idtf:badInput", "idtf: bad"), 1, {M});
%! catch err
%!   assert (err.identifier, "idtf:badInput");
%!   assert (err.message, "idtf: bad");
%! end_try_catch

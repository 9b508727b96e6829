## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn  {} {@var{val} =} subsref (@var{data}, @var{s})
## Read from an @code{iddata} set: @code{data.Name} and
## @code{data(samples, outputs, inputs, experiments)}.
##
## @code{data.Name} returns the property @var{Name} (see @code{help iddata}
## for the list; names are case-insensitive and may be shortened to a
## unique prefix); further subscripts apply to the value, as in
## @code{data.y(1:10)} or @code{data.InputName@{1@}}.  In scripts
## @code{data.y} is the output matrix (a cell of matrices for several
## experiments); code of the control package gets control's cell.
##
## @code{data(i)} selects samples, @code{data(i, j, k, e)} also outputs,
## inputs and experiments (by index or by name).  The selection keeps
## @code{InterSample} and the sampling instants.
## @seealso{iddata, get, subsasgn}
## @end deftypefn

function [val, varargout] = subsref (dat, s, varargin)
  contsid_nargchk ("subsref", nargin, nargout, [2 2], 1);
  check_subs (s, "iddata");
  switch (s(1).type)
    case "()"
      val = index_data (dat, s(1).subs);
    case "."
      name = property_name (s(1).subs, "iddata");
      control_style = called_from_control (name);
      val = property_value (dat, name, control_style);
    otherwise
      error ("iddata:badInput",
             "iddata: use data(...) or data.Name; data{...} is undefined");
  endswitch
  if (numel (s) > 1)
    try
      val = subsref (val, s(2:end));
    catch err
      error ("iddata:badInput", "iddata: %s", err.message);
    end_try_catch
  endif
endfunction

%!shared data, y, u
%! y = (1:10).' / 10;
%! u = [(10:-1:1).', mod((1:10).', 2)];
%! data = iddata (y, u, 0.5, "InterSample", "foh", "InputName", {"a", "b"});

%!test
%! assert (data.y, y);
%! assert (data.Y(2:3), y(2:3));
%! assert (data.u, u);
%! assert (data.InputData(:, 2), u(:, 2));
%! assert (data.Ts, 0.5);
%! assert (data.tsam, {0.5});
%! assert (data.InterSample, "foh");
%! assert (data.inter, "foh");
%! assert (data.InputName{2}, "b");
%! assert (data.Domain, "Time");
%! assert (data.TimeDomain, true);
%! assert (data.SamplingInstants, (0:9).' * 0.5);

%!test
%! part = data(3:4, 1, "b");
%! assert (part.y, y(3:4));
%! assert (part.u, u(3:4, 2));
%! assert (part.InputName, {"b"});
%! assert (part.InterSample, "foh");
%! assert (data(end).y, y(end));
%! assert (data(logical (mod (1:10, 2))).Ts, 1);

## control's functions index data.y as a cell (see called_from_control)
%!test
%! if (! isempty (pkg ("list", "control")))
%!   here = fileparts (fileparts (which ("iddata")));
%!   pkg load control
%!   addpath (here);
%!   [~, p, m, e] = size (data);
%!   x = nkshift (data(:, :, 1), 2);
%!   assert (x.y, y(3:end));
%!   assert (x.u, u(1:end-2, 1));
%! endif

%!error id=iddata:badInput data{1}
%!error id=iddata:badInput data(1, 1, 1, 1, 1)
%!error id=iddata:badInput data(11)
%!error id=iddata:badInput data([2 1])
%!error id=iddata:badInput data(true (1, 11))
%!error id=iddata:badInput data(:, 2)
%!error id=iddata:badInput data(:, :, "c")
%!error id=iddata:badInput data(:, :, 0.5)
%!error id=iddata:badOption data.Bogus
%!error id=iddata:badOption data.In

%!demo
%! data = iddata (sin ((1:200).' / 10), cos ((1:200).' / 10), 0.1, ...
%!                "InterSample", "foh");
%! estimation = data(1:100);    # first half, still first-order hold
%! estimation.InterSample
%! plot (estimation.SamplingInstants, estimation.y)

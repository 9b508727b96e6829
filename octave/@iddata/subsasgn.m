## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{data} =} subsasgn (@var{data}, @var{s}, @var{val})
## Write to an @code{iddata} set: @code{data.Name = val}, also into part of
## a property as in @code{data.y(3) = 0} or @code{data.InputName@{2@} =
## "v"}.  Checks such as equal numbers of samples apply after each
## assignment; to change the length of the signals use @code{set} with all
## of them in one call.  @code{data(k) = other} builds arrays of data sets
## (as the control package's @code{cat} does); other @code{()} assignments
## are not supported.
## @seealso{iddata, set, subsref}
## @end deftypefn

function [dat, varargout] = subsasgn (dat, s, val, varargin)
  contsid_nargchk ("subsasgn", nargin, nargout, [3 3], 1);
  check_subs (s, "iddata");
  switch (s(1).type)
    case "."
      key = s(1).subs;
      name = property_name (key, "iddata");
      if (numel (s) > 1)
        control_style = called_from_control (name);
        try
          val = subsasgn (property_value (dat, name, control_style),
                          s(2:end), val);
        catch err
          error ("iddata:badInput", "iddata: %s", err.message);
        end_try_catch
      endif
      dat = assign_property (dat, name, val, key, "iddata");
      check_dataset (dat, "iddata");
    case "()"
      if (isa (val, "iddata") && numel (s) == 1 && numel (s(1).subs) == 1)
        dat = builtin ("subsasgn", dat, s, val);
      else
        error ("iddata:badInput",
               ["iddata: assign to data.y, data.u or other properties; ", ...
                "data(...) = value is not supported"]);
      endif
    otherwise
      error ("iddata:badInput", "iddata: data{...} = value is undefined");
  endswitch
endfunction

%!shared data
%! data = iddata ((1:5).', (6:10).', 1);

%!test
%! d = data;
%! d.InterSample = "foh";
%! assert (d.InterSample, "foh");
%! d.y(2) = 20;
%! assert (d.y, [1; 20; 3; 4; 5]);
%! d.InputName{1} = "v";
%! assert (d.InputName, {"v"});
%! d.UserData = struct ("gain", 2);
%! assert (d.UserData.gain, 2);
%! assert (d.InterSample, "foh");
%! d.Ts = 0.25;
%! assert (d.SamplingInstants, (0:4).' / 4);
%! d.SamplingInstants = [0 1 3 4 9];
%! assert (d.Ts, []);
%! assert (d.SamplingInstants, [0; 1; 3; 4; 9]);

%!test
%! arr = data;
%! arr(2) = iddata ((1:3).', (1:3).', 2);
%! assert (numel (arr), 2);

%!error id=iddata:badInput data.InterSample = "linear";
%!error id=iddata:badInput data(2) = 3;
%!error id=iddata:badInput data{2} = 3;
%!error id=iddata:badOption data.Domain = "Frequency";
%!error id=iddata:dimensionMismatch data.y = (1:6).';
%!error id=iddata:dimensionMismatch data.SamplingInstants = 1:4;

%!demo
%! data = iddata (randn (100, 1), randn (100, 1), 0.05);
%! data.InterSample = "foh";     # inputs piecewise linear between samples
%! data.OutputName = "speed";
%! data.OutputUnit = "m/s";
%! data

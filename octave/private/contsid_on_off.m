## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{tf} =} contsid_on_off (@var{fname}, @var{name}, @var{v})
## A CONTSID on/off option (@code{Integration} of tfsrivc, tfsrivc_init,
## tfcoe, tfrivc and srivc) as a logical: @qcode{"on"} / @qcode{"off"}
## (any case), or a logical or numeric scalar 0 or 1. Anything else is
## @code{@var{fname}:badOption}.
## @end deftypefn

function tf = contsid_on_off (fname, name, v)
  if (ischar (v) && rows (v) <= 1 && any (strcmpi (v, {"on", "off"})))
    tf = strcmpi (v, "on");
  elseif ((islogical (v) || isnumeric (v)) && isscalar (v) && isreal (v)
          && any (v == [0 1]))
    tf = logical (v);
  else
    error ([fname ":badOption"], "%s: %s must be 'on' or 'off' (or true/false)",
           fname, name);
  endif
endfunction

%!assert (contsid_on_off ("f", "X", "On"), true)
%!assert (contsid_on_off ("f", "X", "off"), false)
%!assert (contsid_on_off ("f", "X", 1), true)
%!assert (contsid_on_off ("f", "X", false), false)
%!error id=f:badOption contsid_on_off ("f", "X", "yes")
%!error id=f:badOption contsid_on_off ("f", "X", 2)
%!error id=f:badOption contsid_on_off ("f", "X", NaN)
%!error id=f:badOption contsid_on_off ("f", "X", [1 0])
%!error id=f:badOption contsid_on_off ("f", "X", {})

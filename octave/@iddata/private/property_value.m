## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{val} =} property_value (@var{dat}, @var{name}, @
##   @var{ctrl})
## Value of the property @var{name} (a canonical name from
## @code{property_name}) of @var{dat}.
##
## With @var{ctrl} false (MATLAB semantics) the signals of a
## single-experiment set come as matrices and a multi-experiment set gives
## a cell with one entry per experiment; @qcode{"Domain"} is
## @qcode{"Time"} or @qcode{"Frequency"}.  With @var{ctrl} true the
## control package's conventions hold: signals always in cells, and
## @qcode{"Domain"} the logical @code{timedomain}.
## @end deftypefn

function val = property_value (dat, name, control_style)
  switch (name)
    case "OutputData"
      val = dat.y;
      if (! control_style)
        val = per_experiment (val);
      endif
    case "InputData"
      val = dat.u;
      if (! control_style)
        if (isempty (val))
          val = cellfun (@(y) zeros (rows (y), 0), dat.y,
                         "uniformoutput", false);
        endif
        val = per_experiment (val);
      endif
    case "OutputName"
      val = dat.outname;
    case "OutputUnit"
      val = dat.outunit;
    case "InputName"
      val = dat.inname;
    case "InputUnit"
      val = dat.inunit;
    case "ExperimentName"
      val = dat.expname;
    case "Ts"
      if (dat.timedomain)
        val = arrayfun (@reported_ts, samplinginfo (dat),
                        "uniformoutput", false);
      else
        val = dat.tsam;
      endif
      val = per_experiment (val);
    case "tsam"
      val = dat.tsam;
    case "SamplingInstants"
      if (dat.timedomain)
        val = per_experiment ({samplinginfo(dat).SamplingInstants}.');
      else
        val = per_experiment (dat.w);
      endif
    case "InterSample"
      [~, val] = unpack_userdata (dat.userdata);
    case "TimeUnit"
      val = dat.timeunit;
    case "Name"
      val = dat.name;
    case "Notes"
      val = dat.notes;
    case "UserData"
      val = unpack_userdata (dat.userdata);
    case "Domain"
      if (control_style)
        val = dat.timedomain;
      elseif (dat.timedomain)
        val = "Time";
      else
        val = "Frequency";
      endif
    case "N"
      val = cellfun ("rows", dat.y(:).');
    case "TimeDomain"
      val = dat.timedomain;
    case "Frequency"
      if (dat.timedomain)
        val = [];
      else
        val = per_experiment (dat.w);
      endif
  endswitch
endfunction

function val = per_experiment (c)
  if (numel (c) == 1)
    val = c{1};
  else
    val = c;
  endif
endfunction

function ts = reported_ts (info)
  if (info.Uniform)
    ts = info.Ts;
  else
    ts = [];
  endif
endfunction

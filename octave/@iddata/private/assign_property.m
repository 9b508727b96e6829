## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{dat} =} assign_property (@var{dat}, @var{name}, @
##   @var{val}, @var{key}, @var{who})
## Assign @var{val} to the property @var{name} (a canonical name from
## @code{property_name}) of @var{dat}.  @var{key} is the name the user
## wrote and @var{who} starts the error messages.  Checks that involve
## several fields (e.g. equal numbers of samples) are left to
## @code{check_dataset}, so that several properties can change in one call.
## @end deftypefn

function dat = assign_property (dat, name, val, key, who)
  nexp = numel (dat.y);
  switch (name)
    case "OutputData"
      y = signal_cells (val, key, who, true);
      check_channels (y, numel (dat.outname), nexp, key, who, "outputs");
      dat.y = y;
    case "InputData"
      u = signal_cells (val, key, who, false);
      check_channels (u, numel (dat.inname), nexp, key, who, "inputs");
      dat.u = u;
    case "OutputName"
      dat.outname = labels (val, numel (dat.outname), key, who);
    case "OutputUnit"
      dat.outunit = labels (val, numel (dat.outname), key, who);
    case "InputName"
      dat.inname = labels (val, numel (dat.inname), key, who);
    case "InputUnit"
      dat.inunit = labels (val, numel (dat.inname), key, who);
    case "ExperimentName"
      dat.expname = labels (val, nexp, key, who);
    case {"Ts", "tsam"}
      dat = apply_sampling (dat, val, key, who);
    case "SamplingInstants"
      dat = apply_sampling (dat, val, key, who, "instants");
    case "InterSample"
      if (iscellstr (val) && ! isempty (val)
          && all (strcmpi (val, val{1})))
        val = val{1};
      endif
      if (iscellstr (val) && numel (val) > 1)
        error ("iddata:notSupported",
               ["%s: '%s': one inter-sample behaviour for all inputs ", ...
                "(got %s)"], who, key, strjoin (val(:).', ", "));
      endif
      if (! (ischar (val) && any (strcmpi (val, {"zoh", "foh", "bl"}))))
        error ("iddata:badInput",
               "%s: '%s' must be \"zoh\", \"foh\" or \"bl\"", who, key);
      endif
      userdata = unpack_userdata (dat.userdata);
      dat.userdata = pack_userdata (userdata, lower (val), true);
    case "UserData"
      [~, intersample, given] = unpack_userdata (dat.userdata);
      dat.userdata = pack_userdata (val, intersample, given);
    case {"TimeUnit", "Name"}
      if (! (ischar (val) && rows (val) <= 1))
        error ("iddata:badInput", "%s: '%s' must be a string", who, key);
      endif
      if (strcmp (name, "Name"))
        dat.name = val;
      else
        dat.timeunit = val;
      endif
    case "Notes"
      if (ischar (val) && rows (val) <= 1)
        val = {val};
      elseif (! iscellstr (val))
        error ("iddata:badInput",
               "%s: '%s' must be a string or a cell of strings", who, key);
      endif
      dat.notes = val;
    case "Frequency"
      dat = apply_frequency (dat, val, key, who);
    otherwise
      error ("iddata:badOption", "%s: property '%s' is read-only",
             who, key);
  endswitch
endfunction

function check_channels (c, nchan, nexp, key, who, what)
  if (! isempty (c) && numel (c) != nexp)
    error ("iddata:dimensionMismatch",
           "%s: '%s' has %d experiments instead of %d", who, key,
           numel (c), nexp);
  endif
  ncols = cellfun ("columns", c);
  if (isempty (c) && nchan != 0 || any (ncols != nchan))
    error ("iddata:dimensionMismatch",
           "%s: '%s' must have %d %s (columns)", who, key, nchan, what);
  endif
endfunction

function names = labels (val, n, key, who)
  if (ischar (val) && rows (val) <= 1)
    val = {val};
  endif
  if (! iscellstr (val) || numel (val) != n)
    error ("iddata:dimensionMismatch",
           "%s: '%s' must be a string or a cell of %d strings", who, key, n);
  endif
  names = val(:);
endfunction

function dat = apply_frequency (dat, val, key, who)
  nexp = numel (dat.y);
  if (! iscell (val))
    val = {val};
  endif
  if (numel (val) == 1)
    val = repmat (val, nexp, 1);
  endif
  if (numel (val) != nexp || ! all (cellfun (@is_frequency_vector, val)))
    error ("iddata:badInput",
           ["%s: '%s' must be increasing non-negative frequencies ", ...
            "(a cell with one vector per experiment)"], who, key);
  endif
  dat.w = cellfun (@(w) double (w(:)), val(:), "uniformoutput", false);
  dat.timedomain = false;
endfunction

function ok = is_frequency_vector (w)
  ok = (isnumeric (w) && isreal (w) && isvector (w) && all (isfinite (w))
        && all (w >= 0) && all (diff (w) > 0));
endfunction

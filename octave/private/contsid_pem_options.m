## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{opt} =} contsid_pem_options (@var{fname}, @var{args})
## The option set of @code{oeOptions} and @code{tfestOptions}: defaults,
## then the name-value pairs @var{args}, each checked.
## @end deftypefn

function opt = contsid_pem_options (fname, args)
  opt = struct ("OptionSet", fname, "Focus", "simulation",
                "InitialCondition", "zero", "Display", "off",
                "SearchMethod", "lm",
                "SearchOptions",
                struct ("MaxIterations", contsid_pem_default ("maxiter"),
                        "Tolerance", contsid_pem_default ("tol")));
  if (mod (numel (args), 2) != 0)
    error ([fname ":badOption"], "%s: options come in name-value pairs",
           fname);
  endif
  names = {"Focus", "InitialCondition", "Display", "SearchMethod", ...
           "SearchOptions"};
  for i = 1:2:numel (args)
    if (! ischar (args{i}))
      error ([fname ":badOption"], "%s: option names must be strings", fname);
    endif
    k = find (strcmpi (args{i}, names));
    if (isempty (k))
      error ([fname ":badOption"], "%s: unknown option '%s'", fname, args{i});
    endif
    v = args{i+1};
    switch (names{k})
      case "Focus"
        ok = ((ischar (v) && any (strcmpi (v, {"simulation", "prediction"})))
              || (isnumeric (v) && isreal (v) && numel (v) == 2
                  && all (isfinite (v)) && v(1) >= 0 && v(2) > v(1)));
      case "InitialCondition"
        ok = ischar (v) && any (strcmpi (v, {"zero", "auto"}));
      case "Display"
        ok = ischar (v) && any (strcmpi (v, {"on", "off"}));
      case "SearchMethod"
        ok = ischar (v) && any (strcmpi (v, {"lm", "auto"}));
      case "SearchOptions"
        ok = (isstruct (v) && isscalar (v)
              && all (isfield (v, {"MaxIterations", "Tolerance"})));
    endswitch
    if (! ok)
      error ([fname ":badOption"], "%s: bad value for '%s'", fname,
             names{k});
    endif
    opt.(names{k}) = v;
  endfor
endfunction

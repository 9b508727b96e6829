## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {} display (@var{data})
## Print a summary of an @code{iddata} set: domain, numbers of channels,
## the sampling of each experiment, the inter-sample behaviour and the
## channel names and units.
## @seealso{iddata, get}
## @end deftypefn

function varargout = display (dat, varargin)
  contsid_nargchk ("display", nargin, nargout, [1 1], 0);
  [n, ny, nu, ne] = size (dat);
  plural = {"", "s"};
  printf ("%s =\n\n", inputname (1, false));
  if (dat.timedomain)
    printf ("  Time-domain data set");
  else
    printf ("  Frequency-domain data set");
  endif
  printf (" with %d output%s, %d input%s and %d experiment%s\n",
          ny, plural{1 + (ny != 1)}, nu, plural{1 + (nu != 1)},
          ne, plural{1 + (ne != 1)});
  [~, intersample] = unpack_userdata (dat.userdata);
  if (dat.timedomain && nu > 0)
    printf ("  InterSample: %s\n", intersample);
  endif
  printf ("\n");

  unit = "";
  if (! isempty (dat.timeunit))
    unit = [" ", dat.timeunit];
  endif
  expnames = default_names (dat.expname, "exp");
  if (dat.timedomain)
    info = samplinginfo (dat);
  endif
  for k = 1:ne
    if (! dat.timedomain)
      w = dat.w{k};
      sampling = sprintf ("frequencies %g ... %g%s", w(1), w(end),
                          ts_note (dat.tsam{k}));
    elseif (! info(k).Uniform)
      t = info(k).SamplingInstants;
      sampling = sprintf ("irregular, t = %g ... %g%s", t(1), t(end), unit);
    elseif (info(k).Ts > 0)
      sampling = sprintf ("Ts = %g%s", info(k).Ts, unit);
    else
      sampling = "Ts unspecified";
    endif
    printf ("  %-12s %8d samples   %s\n", expnames{k}, n(k), sampling);
  endfor
  printf ("\n");
  print_channels ("Output", default_names (dat.outname, "y"), dat.outunit);
  print_channels ("Input", default_names (dat.inname, "u"), dat.inunit);
endfunction

function str = ts_note (ts)
  if (ts == 0)
    str = " (continuous time)";
  elseif (ts > 0)
    str = sprintf (" (Ts = %g)", ts);
  else
    str = "";
  endif
endfunction

function names = default_names (names, prefix)
  for k = find (cellfun ("isempty", names(:).'))
    names{k} = sprintf ("%s%d", prefix, k);
  endfor
endfunction

function print_channels (title, names, units)
  if (isempty (names))
    return;
  endif
  width = max ([cellfun("numel", names(:).'), numel(title) + 1]);
  lines = [{sprintf("  %-*s  Unit", width, [title, "s"])};
           cellfun(@(name, unit) sprintf ("  %-*s  %s", width, name, unit),
                   names(:), units(:), "uniformoutput", false)];
  printf ("%s\n", deblank (lines){:});
  printf ("\n");
endfunction

%!test
%! t = [0; 0.5; 0.7; 2];
%! data = iddata (t, t, t, "InterSample", "foh", "OutputName", "level");
%! text = evalc ("display (data)");
%! assert (! isempty (strfind (text, "irregular, t = 0 ... 2")));
%! assert (! isempty (strfind (text, "InterSample: foh")));
%! assert (! isempty (strfind (text, "level")));
%! text = evalc ("data = iddata ((1:3).', [], 0.5)");
%! assert (! isempty (strfind (text, "Ts = 0.5")));
%! text = evalc ("data = iddata ([1; 2], [], 0, 'Frequency', [0; 1])");
%! assert (! isempty (strfind (text, "frequencies 0 ... 1 (continuous time)")));

%!demo
%! data = iddata (randn (100, 1), randn (100, 1), 0.01, "InterSample", "foh");
%! data.OutputName = "temperature";
%! data.OutputUnit = "K";
%! data

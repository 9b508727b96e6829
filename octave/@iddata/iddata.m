## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn  {} {@var{data} =} iddata (@var{y}, @var{u}, @var{Ts})
## @deftypefnx {} {@var{data} =} iddata (@var{y}, @var{u}, @var{t})
## @deftypefnx {} {@var{data} =} iddata (@var{y}, @var{u}, @var{Ts}, @
##   @var{name}, @var{value}, @dots{})
## @deftypefnx {} {@var{data} =} iddata ([], @var{u}, @var{Ts}, @dots{})
## @deftypefnx {} {@var{data} =} iddata (@var{Y}, @var{U}, @var{Ts}, @
##   "Frequency", @var{w}, @dots{})
## @deftypefnx {} {@var{data} =} iddata (@var{y})
## @deftypefnx {} {@var{data} =} iddata (@var{data})
## @deftypefnx {} {@var{data} =} iddata ()
## Identification data set: sampled outputs and inputs of a system.
##
## This is the class the CONTSID routines read their data from.  It takes
## the MATLAB / CONTSID calls, including
## @code{iddata (y, u, Ts, "InterSample", "foh")} and irregular sampling,
## and it is the same class as the control package's @code{iddata}: the
## objects have control's field layout, so control's functions
## (@code{arx}, @code{moen4}, @code{detrend}, @dots{}) work on them and
## objects built by either constructor live together in one session.
##
## @strong{Inputs}
## @table @var
## @item y
## @var{N}-by-@var{ny} output signal, one row per sample (a row vector is
## taken as one signal).  For several experiments, a cell with one matrix
## per experiment (control's form).
## @var{y} = @code{[]} with a non-empty @var{u} gives input-only data
## (@var{N}-by-0 outputs), as CONTSID's @code{simc} reads them.
## @item u
## @var{N}-by-@var{nu} input signal, or @code{[]} for a time series
## (output-only data).
## @item Ts
## sampling interval (positive scalar), or -1 / @code{[]} for unspecified.
## @item t
## @var{N}-vector of increasing sampling instants (irregular sampling).
## For several experiments, a cell with one @var{Ts} or @var{t} each.
## @end table
##
## @strong{Properties} (names are case-insensitive, unique prefixes are
## accepted; read with @code{data.Name} or @code{get}, write with
## @code{data.Name = value} or @code{set}):
## @table @code
## @item OutputData, y
## the outputs: a matrix, or for several experiments a cell of matrices.
## @item InputData, u
## the inputs, likewise.
## @item Ts
## sampling interval; @code{[]} for irregularly sampled experiments.
## @item tsam
## control's sampling-time cell, one scalar per experiment (-1 when
## irregular or unspecified).
## @item SamplingInstants
## @var{N}-by-1 sampling instants (@code{(0:N-1)'*Ts} when regular).
## Setting it makes the sampling irregular.
## @item InterSample
## @qcode{"zoh"} (default), @qcode{"foh"} or @qcode{"bl"}: how the inputs
## behave between samples (piecewise constant, piecewise linear or
## band-limited); one value for all inputs (a cell of equal values is
## accepted, mixed values are @code{iddata:notSupported}).
## @item N
## read-only: the number of samples (frequencies), a row with one entry
## per experiment.
## @item OutputName, OutputUnit, InputName, InputUnit, ExperimentName
## cell arrays of strings (control: @code{outname}, @dots{}).
## @item TimeUnit, Name, Notes, UserData
## free text and the user's own data.
## @item Domain, TimeDomain
## read-only: @qcode{"Time"} or @qcode{"Frequency"}, and control's logical.
## @item Frequency, w
## frequencies of a frequency-domain set (as in the control package):
## giving them to the constructor builds a frequency-domain set, where the
## signals may be complex and @code{Ts = 0} marks continuous-time
## frequencies (rad/@var{TimeUnit}).
## @end table
##
## @strong{Storage.}  The object is a struct with control's fields, in
## control's order: @code{y, outname, outunit, u, inname, inunit, tsam,
## timeunit, timedomain, w, expname, name, notes, userdata}.  The two
## things control has no field for are stored so that control's code never
## misreads them:
## @itemize
## @item Irregular sampling instants go to @code{w}, which control only
## reads for frequency-domain sets (@code{timedomain} false).  For a
## time-domain set @code{w} is @code{@{@}} when every experiment is
## regularly sampled, as in control's objects; otherwise it holds one
## column of instants per experiment (@code{[]} for regular ones), and
## @code{tsam} is -1 (unspecified) for the irregular experiments.  Control's
## own @code{get (data, "SamplingInstants")} returns @code{w} too.
## @item @code{InterSample} goes to @code{userdata}.  With the default
## @qcode{"zoh"} (not given) the field holds the user's @code{UserData}
## unchanged, so an object built here without InterSample equals the one
## control builds.  When InterSample is given (also @qcode{"zoh"}: CONTSID
## chooses the interpolation of irregularly sampled inputs whose
## InterSample is not given, see @code{samplinginfo}) it holds the struct
## @code{struct ("InterSample", "foh", "UserData", @var{userdata})};
## @code{data.UserData} and @code{get}/@code{set} still give and take the
## user's own value.
## @end itemize
##
## @strong{Signals in MATLAB and in the control package.}  MATLAB gives
## @code{data.y} as a matrix, the control package as a cell with one matrix
## per experiment, and control's functions rely on the cell.  Here
## @code{data.y} (and @code{u}, @code{OutputData}, @code{InputData}) gives
## the cell when the code asking is part of the control package and the
## matrix otherwise (in scripts, at the command line and in this toolbox).
## @code{data.tsam} is always control's cell, @code{data.Ts} always
## MATLAB's value.
##
## @strong{Precedence over the control package.}  Octave uses the first
## @code{@@iddata/iddata.m} on the path.  Adding this toolbox with
## @code{addpath} loads the control package (when installed) and puts this
## folder in front of it (see @file{PKG_ADD}), so that a later
## @code{pkg load control} keeps this constructor.  After
## @code{pkg unload control; pkg load control}, run @code{addpath} again.
##
## Indexing @code{data(samples, outputs, inputs, experiments)} selects
## samples (increasing indices) and channels and keeps @code{InterSample}
## and the sampling instants; selecting every k-th sample of regularly
## sampled data multiplies @code{Ts} by k, and an uneven selection turns
## into sampling instants.  Regularly sampled data start at time 0.
##
## @strong{Methods.}  Besides @code{get}, @code{set}, @code{size} and
## indexing, this class replaces the control package's methods that lost
## the inter-sample behaviour or the sampling instants: @code{cat},
## @code{vertcat} (@code{[d1; d2]}), @code{horzcat} (@code{[d1, d2]}) and
## @code{merge} keep @code{InterSample} and the instants, or refuse with an
## identified error (different @code{InterSample}, different @code{Ts},
## instants that do not follow each other); @code{nkshift}, @code{diff} and
## @code{resample} shorten the instants with the signals; @code{detrend}
## (break points, trend struct) fits against the sampling instants;
## @code{fft} and @code{ifft} are exact inverses for every length;
## @code{plot} takes line styles (@code{plot (d1, "b", d2, "r")}).  Also:
## @code{getexp}, @code{idresamp}, @code{idplot}.  The control package's
## @code{filter} still applies (to regularly sampled data).
##
## @strong{Limits.}  Octave 7 reports an error raised inside a class's
## concatenation method called by the operator (@code{[d1; d2]}) only as
## @qcode{"iddata/vertcat method failed"}, without identifier; the reason
## is issued just before as a warning with the identifier, and the function
## form @code{vertcat (d1, d2)} raises the identified error itself.  Data with
## unspecified sampling interval (@code{iddata (y, u)}) are rejected by the
## toolbox's estimators.
##
## @strong{Example}
## @example
## @group
## u = prbs (7, 4);
## y = filter (0.1, [1, -0.9], u);
## data = iddata (y, u, 0.01, "InterSample", "zoh");
## data.Ts
##   @result{} 0.0100
## sz = size (data(1:100))
##   @result{} sz = 100     1     1     1
## @end group
## @end example
## @seealso{samplinginfo, get, set, size, merge, detrend, fft, plot,
## idresamp, idplot}
## @end deftypefn

function varargout = iddata (varargin)
  varargout = contsid_guard ({"iddata", "iddata"}, @iddata_body, nargout,
                             varargin);
endfunction

function [dat, varargout] = iddata_body (varargin)
  contsid_nargchk ("iddata", nargin, nargout, [0 Inf], 1);
  if (nargin == 1 && isa (varargin{1}, "iddata"))
    dat = varargin{1};
    return;
  endif

  npos = find (cellfun ("ischar", varargin), 1) - 1;
  if (isempty (npos))
    npos = min (nargin, 3);
  endif
  npos = min (npos, 3);
  if (npos == 0 && nargin > 0)
    error ("iddata:badInput", "iddata: the outputs 'y' must come first");
  endif
  positional = [varargin(1:npos), cell(1, 3 - npos)];
  [y, u, ts] = positional{:};
  pairs = varargin(npos+1:end);

  if (! iscell (y) && isrow (y) && numel (y) > 1)
    y = y.';
  endif
  if (! iscell (u) && ! iscell (y) && isrow (u) && numel (u) > 1
      && numel (u) == rows (y))
    u = u.';
  endif
  y = signal_cells (y, "y", "iddata", true);
  u = signal_cells (u, "u", "iddata", false);
  if (isempty (y{1}) && numel (y) == 1 && ! isempty (u))
    ## input-only data iddata ([], u, ...): N-by-0 outputs per experiment
    y = cellfun (@(x) zeros (rows (x), 0), u, "uniformoutput", false);
  endif
  nexp = numel (y);
  nout = columns (y{1});
  nin = 0;
  if (! isempty (u))
    nin = columns (u{1});
  endif

  blank = @(n) repmat ({""}, n, 1);
  dat = struct ("y", {y}, "outname", {blank(nout)}, "outunit", {blank(nout)},
                "u", {u}, "inname", {blank(nin)}, "inunit", {blank(nin)},
                "tsam", {repmat({-1}, nexp, 1)}, "timeunit", "",
                "timedomain", true, "w", {{}}, "expname", {blank(nexp)},
                "name", "", "notes", {{}}, "userdata", []);
  dat = class (dat, "iddata");
  if (mod (numel (pairs), 2) != 0)
    error ("iddata:badOption",
           "iddata: properties must come in name-value pairs");
  endif
  ## 'Frequency' first: it makes the set frequency-domain, where complex
  ## signals and Ts = 0 (continuous-time frequencies) are allowed
  names = cellfun (@(key) property_name (key, "iddata"), pairs(1:2:end),
                   "uniformoutput", false);
  isfreq = find (strcmp (names, "Frequency"));
  for k = isfreq
    dat = assign_property (dat, "Frequency", pairs{2*k}, pairs{2*k-1},
                           "iddata");
  endfor
  pairs(sort ([2*isfreq-1, 2*isfreq])) = [];
  check_dataset (dat, "iddata");
  dat = apply_sampling (dat, ts, "Ts", "iddata");

  for k = 1:2:numel (pairs)
    name = property_name (pairs{k}, "iddata");
    dat = assign_property (dat, name, pairs{k+1}, pairs{k}, "iddata");
  endfor
  check_dataset (dat, "iddata");
endfunction

%!shared y, u, t
%! t = (0:99).' * 0.1;
%! y = sin (t);
%! u = sign (sin (0.7 * t));

%!test
%! data = iddata (y, u, 0.1, "InterSample", "zoh");
%! assert (isa (data, "iddata"));
%! assert (data.y, y);
%! assert (data.u, u);
%! assert (data.Ts, 0.1);
%! assert (data.tsam, {0.1});
%! assert (data.InterSample, "zoh");
%! assert (data.SamplingInstants, t, 1e-12);
%! assert (data.OutputData, y);
%! assert (data.InputData, u);
%! assert (size (data), [100, 1, 1, 1]);
%! assert (fieldnames (struct (data)),
%!         {"y"; "outname"; "outunit"; "u"; "inname"; "inunit"; "tsam";
%!          "timeunit"; "timedomain"; "w"; "expname"; "name"; "notes";
%!          "userdata"});

%!test
%! data = iddata (y, u, 0.1, "intersample", "FOH", "UserData", {1, "a"});
%! assert (data.InterSample, "foh");
%! assert (data.UserData, {1, "a"});
%! s = struct (data);
%! assert (s.userdata, struct ("InterSample", "foh", "UserData", {{1, "a"}}));
%! data.InterSample = "zoh";
%! assert (data.UserData, {1, "a"});
%! assert (struct (data).userdata,
%!         struct ("InterSample", "zoh", "UserData", {{1, "a"}}));
%! ## the default (InterSample not given) is stored as control stores it
%! assert (struct (iddata (y, u, 0.1, "UserData", 3)).userdata, 3);
%! assert (! samplinginfo (iddata (y, u, 0.1)).InterSampleGiven);
%! assert (samplinginfo (iddata (y, u, 0.1, "InterSample",
%!                               "zoh")).InterSampleGiven);

## InterSample and irregular instants survive sample indexing
%!test
%! ti = cumsum ([0; 0.1 + 0.01*mod((1:99).', 7)]);
%! data = iddata (y, u, ti, "InterSample", "foh");
%! assert (data.Ts, []);
%! assert (data.tsam, {-1});
%! assert (data.SamplingInstants, ti);
%! part = data(11:20);
%! assert (part.InterSample, "foh");
%! assert (part.SamplingInstants, ti(11:20));
%! assert (part.y, y(11:20));
%! reg = iddata (y, u, 0.1, "InterSample", "foh");
%! assert (reg(1:50).InterSample, "foh");
%! assert (reg(1:2:end).Ts, 0.2, 1e-15);
%! assert (reg([1 2 5]).SamplingInstants, [0; 0.1; 0.4], 1e-15);

## row vectors are single signals; a zero-argument call gives an empty set
%!test
%! data = iddata (y.', u.', 0.1);
%! assert (size (data), [100, 1, 1, 1]);
%! assert (size (iddata ()), [0, 0, 0, 1]);
%! assert (struct (iddata (data)), struct (data));
%! ts = iddata (y, [], 0.1);
%! assert (size (ts), [100, 1, 0, 1]);

## input-only and output-only data; the property N
%!test
%! datau = iddata ([], [u, -u], 0.1, "InterSample", {"foh"; "foh"});
%! assert (size (datau), [100, 0, 2, 1]);
%! assert (size (datau.y), [100, 0]);
%! assert (datau.u, [u, -u]);
%! assert (datau.InterSample, "foh");
%! assert (datau.N, 100);
%! datai = iddata ([], u, "SamplingInstants", t.^2);
%! assert (datai.SamplingInstants, t.^2);
%! assert (size (datai), [100, 0, 1, 1]);
%! datay = iddata (y, [], 0.1);
%! assert (size (datay), [100, 1, 0, 1]);
%! assert (size (datay.u), [100, 0]);
%! assert (iddata ({y, y(1:10)}, {u, u(1:10)}, 0.1).N, [100, 10]);
%! assert (iddata ([], {u, u(1:10)}, 0.1).N, [100, 10]);
%! assert (iddata (y, u, 0.1, "intersamp", "bl").InterSample, "bl");

## frequency-domain data with continuous-time frequencies
%!test
%! w = (0:49).' * 0.3;
%! Y = exp (1i * w);
%! dat = iddata (Y, [], 0, "Frequency", w);
%! assert (dat.Domain, "Frequency");
%! assert (dat.Frequency, w);
%! assert (dat.Ts, 0);
%! assert (dat.y, Y);
%! assert (dat.N, 50);

## several experiments, control's cell form
%!test
%! data = iddata ({y, y(1:50)}, {u, u(1:50)}, {0.1, t(1:50)});
%! assert (size (data), [150, 1, 1, 2]);
%! assert (data.Ts, {0.1; []});
%! assert (data.SamplingInstants{2}, t(1:50));
%! assert (data.y, {y; y(1:50)});

## without the control package loaded
%!test
%! if (! isempty (pkg ("list", "control")))
%!   here = fileparts (fileparts (which ("iddata")));
%!   pkg unload control
%!   unwind_protect
%!     assert (isempty (which ("moen4")));
%!     data = iddata (y, u, 0.1, "InterSample", "foh");
%!     assert (data.InterSample, "foh");
%!     assert (data(1:10).y, y(1:10));
%!     assert (size (data), [100, 1, 1, 1]);
%!   unwind_protect_cleanup
%!     pkg load control
%!     addpath (here);
%!   end_unwind_protect
%! endif

## with the control package loaded: control's functions read our objects
%!test
%! if (! isempty (pkg ("list", "control")))
%!   pkg load control
%!   data = iddata (y, u, 0.1, "InterSample", "foh");
%!   assert (data.InterSample, "foh");
%!   sys = arx (data, 2);
%!   assert (isa (sys, "tf"));
%!   assert (sys.tsam, 0.1);
%!   both = [data; data];
%!   assert (size (both), [200, 1, 1, 1]);
%!   data = iddata (filter ([0, 0.2], [1, -0.8], u), u, 0.1);
%!   warning ("off", "all", "local");   # noise-free data: exact fit
%!   sys = moen4 (data, 1);
%!   assert (pole (sys), 0.8, 1e-8);
%! endif

%!error id=iddata:badInput iddata ("InterSample", "zoh")
%!error id=iddata:badInput iddata ({1, "a"})
%!error id=iddata:badInput iddata ((1:3).', (1:3).', 0)
%!error id=iddata:badInput iddata ((1:3).', (1:3).', NaN)
%!error id=iddata:badInput iddata ((1:3).', (1:3).', [0 2 1])
%!error id=iddata:badInput iddata ((1:3).', (1:3).', {"a"})
%!error id=iddata:badInput iddata ({1:3, 1:3}, {}, [1 2])
%!error id=iddata:badInput iddata ((1:3).', [1; 2; 3i], 1)
%!error id=iddata:badInput iddata ((1:3).', (1:3).', 1, "InterSample", "xoh")
%!error id=iddata:notSupported
%! iddata ((1:3).', [1:3; 1:3].', 1, "InterSample", {"zoh"; "foh"});
%!error id=iddata:badInput iddata ((1:3).', [], 0)
%!error id=iddata:badOption iddata ((1:3).', [], 1, "N", 3)
%!error id=iddata:badInput iddata ((1:3).', (1:3).', 1, "Name", 3)
%!error id=iddata:badInput iddata ((1:3).', (1:3).', 1, "Notes", 3)
%!error id=iddata:badInput iddata ((1:3).', (1:3).', 1, "w", [2 1 0])
%!error id=iddata:badInput iddata ((1:3).', (1:3).', 1, "w", 0:2, "Ts", 1:3)
%!error id=iddata:dimensionMismatch iddata ((1:3).', (1:4).', 1)
%!error id=iddata:dimensionMismatch iddata ((1:3).', (1:3).', 1:4)
%!error id=iddata:dimensionMismatch iddata ({1:3, 1:3}, {1:3, 1:3}, {1, 1, 1})
%!error id=iddata:dimensionMismatch iddata ({1:3, 1:3}, {1:3})
%!error id=iddata:dimensionMismatch iddata ({ones(3, 1), ones(3, 2)})
%!error id=iddata:dimensionMismatch iddata ({ones(3, 1), ones(3, 1)},
%!                                          {ones(3, 1), ones(3, 2)})
%!error id=iddata:dimensionMismatch iddata ((1:3).', (1:3).', 1, "w", 0:3)
%!error id=iddata:dimensionMismatch iddata (ones (3, 2), [], 1, "outname", "a")
%!error id=iddata:dimensionMismatch iddata ((1:3).', [], 1, "u", (1:3).')
%!error id=iddata:dimensionMismatch iddata ((1:3).', (1:3).', 1, "y", [])
%!error id=iddata:dimensionMismatch iddata ({(1:3).'}, {(1:3).'}, 1, ...
%!                                          "y", {(1:3).', (1:3).'})
%!error id=iddata:badOption iddata ((1:3).', (1:3).', 1, "InterSample")
%!error id=iddata:badOption iddata ((1:3).', (1:3).', 1, "Bogus", 1)
%!error id=iddata:badOption iddata ((1:3).', (1:3).', 1, "in", 1)
%!error id=iddata:badOption iddata ((1:3).', (1:3).', 1, 2, 1)
%!error id=iddata:badOption iddata ((1:3).', (1:3).', 1, "Domain", "Time")

%!demo
%! ## a CONTSID-style data set: PRBS input held for 4 samples, first-order
%! ## plant, sampled every 10 ms, inputs piecewise constant between samples
%! u = prbs (7, 4);
%! y = filter (0.1, [1, -0.9], u);
%! data = iddata (y, u, 0.01, "InterSample", "zoh")
%! first = data(1:100);
%! first.Ts

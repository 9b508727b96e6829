## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn  {} {[@var{c}, @var{d}] =} contsid_carried_levels (@var{M}, @var{nu})
## @deftypefnx {} {[@var{c}, @var{d}] =} contsid_carried_levels (@var{M}, @var{nu}, @var{fname}, @var{mode}, @var{ny})
## The levels a model carries, read in one place for every function that
## simulates, compares or analyses a model (doc/manual/levels.md,
## @code{help idpoly}): the output levels @var{c} (1-by-@var{ny}) and the
## input levels @var{d} (1-by-@var{nu}) of
## @code{M.Report.DataUsed.OutputOffset} and @code{InputOffset}, the
## offsets removed from the data it was estimated on (MATLAB's
## convention), so that the model as estimated is
## y - c = M (u - d), from rest at those levels.  Zeros for a model that
## carries none (empty fields, no Report, a struct, a control tf/ss, a
## recursive estimate THM).
##
## @var{mode} is the value of the @code{"Levels"} option of the calling
## function @var{fname}: @qcode{"carried"} (the default) or
## @qcode{"ignore"} (zeros: the model alone, MATLAB's @code{sim} and
## @code{compare}, the user removes the offsets from the data).  A
## scalar offset holds for every input (output).  Levels of the wrong
## size or not finite are an error @code{@var{fname}:badInput}: a model
## that cannot be simulated as estimated is not simulated otherwise.
## @end deftypefn

function [c, d] = contsid_carried_levels (M, nu, fname = "simc",
                                          mode = "carried", ny = 1)
  if (! ischar (mode) || ! any (strcmpi (mode, {"carried", "ignore"})))
    error ([fname ":badOption"],
           "%s: Levels must be 'carried' (the default) or 'ignore'", fname);
  endif
  c = zeros (1, ny);
  d = zeros (1, nu);
  if (strcmpi (mode, "ignore") || ! isobject (M))
    return;
  endif
  try
    lev = get (M, "Report").DataUsed;
  catch
    return;                            # a model class without a Report
  end_try_catch
  c = read_level (lev, "OutputOffset", ny, fname);
  d = read_level (lev, "InputOffset", nu, fname);
endfunction

function v = read_level (lev, name, n, fname)
  v = zeros (1, n);
  if (! isfield (lev, name) || isempty (lev.(name)))
    return;
  endif
  x = lev.(name);
  if (! isnumeric (x) || ! isreal (x) || ! any (numel (x) == [1 n])
      || any (! isfinite (x(:))))
    error ([fname ":badInput"],
           ["%s: the model's Report.DataUsed.%s must be empty, a finite ", ...
            "scalar or %d finite values"], fname, name, n);
  endif
  v(:) = double (x(:).');
endfunction

%!test  # srivc's levels on an idpoly; none on a built model or a struct
%! M = idpoly (1, 2, 1, 1, [1 1], "Ts", 0);
%! [c, d] = contsid_carried_levels (M, 1);
%! assert ([c, d], [0 0]);
%! M.Report.DataUsed.OutputOffset = 20;
%! M.Report.DataUsed.InputOffset = 5;
%! [c, d] = contsid_carried_levels (M, 1);
%! assert ([c, d], [20 5]);
%! [c, d] = contsid_carried_levels (M, 1, "simc", "ignore");
%! assert ([c, d], [0 0]);
%! [c, d] = contsid_carried_levels (struct ("B", 1, "F", [1 1]), 2);
%! assert ([c, d], [0 0 0]);
%! M.Report.DataUsed.InputOffset = 5;
%! [c, d] = contsid_carried_levels (M, 3, "simc", "carried", 2);
%! assert (c, [20 20]);
%! assert (d, [5 5 5]);
%!error id=comparec:badOption contsid_carried_levels (idtf (1, [1 1]), 1, "comparec", "raw")
%!test
%! M = idtf (1, [1 1]);
%! M.Report.DataUsed.InputOffset = [1 2];
%! fail ("contsid_carried_levels (M, 1, 'sim')", "sim: the model's Report");

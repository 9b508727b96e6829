## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {[@var{u}, @var{y}, @var{spill}] =} greybox_record ("tanks", @var{N}, @var{Ts}, @var{p})
## @deftypefnx {} {[@var{u}, @var{y}] =} greybox_record ("axis", @var{N}, @var{Ts}, @var{p})
## One record of the grey-box rigs of @code{demo_greybox}, drawn from the
## current state of @code{rand} and @code{randn}.
##
## @code{"tanks"}: the pump voltage holds random levels (2.5 to 7.5 V) for
## random times (40 to 300 s); @var{y} is the level of the lower tank of
## @code{tanks_sim} (parameters @var{p}) plus noise of sd 0.3 cm;
## @var{spill} is true where the upper tank overflows.
##
## @code{"axis"}: the reference is a random staircase between 0 and 10 V
## (steps held 0.8 to 2.8 s), smoothed by a first-order filter of 0.3 s
## (the operator's set-point ramps); @var{y} is the carriage position of
## @code{axis_sim} (parameters @var{p}) plus noise of sd 0.05 mm.
##
## Used by @code{demo_greybox} and @code{bench/residtrace_rigs_bench.m}.
## @end deftypefn

function [u, y, spill] = greybox_record (rig, N, Ts, p)
  switch (rig)
    case "tanks"
      u = zeros (N, 1);
      k = 1;
      while (k <= N)
        L = round ((40 + 260 * rand) / Ts);
        u(k:min (N, k + L - 1)) = 2.5 + 5 * rand;
        k += L;
      endwhile
      [h2, ~, spill] = tanks_sim (u, Ts, p);
      y = h2 + 0.3 * randn (N, 1);
    case "axis"
      s = zeros (N, 1);
      k = 1;
      while (k <= N)
        L = round ((0.8 + 2 * rand) / Ts);
        s(k:min (N, k + L - 1)) = 10 * rand;
        k += L;
      endwhile
      u = filter (Ts / 0.3, [1, Ts / 0.3 - 1], s, s(1) * (1 - Ts / 0.3));
      y = axis_sim (u, Ts, p) + 0.05 * randn (N, 1);
      spill = [];
    otherwise
      error ("greybox_record:badInput",
             "greybox_record: RIG must be \"tanks\" or \"axis\"");
  endswitch
endfunction

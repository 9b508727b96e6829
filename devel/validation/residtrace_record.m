## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {[@var{R}, @var{M}] =} residtrace_record (@var{y}, @var{u}, @var{yv}, @var{uv}, @var{Ts}, @var{nn}, @dots{})
## residtrace on a record as a user would run it: the model @var{M} is
## SRIVC of the plain linear structure @var{nn} on the estimation record
## (@var{y}, @var{u}) with its means removed, then @code{residtrace} on
## the raw records, the validation record (@var{yv}, @var{uv}) apart,
## both zero-order hold; further arguments are residtrace's options. Used
## by @code{residtrace_sim_records} and by the tests of residtrace's physical
## realisations.
## @end deftypefn

function [R, M] = residtrace_record (y, u, yv, uv, Ts, nn, varargin)
  d = iddata (y, u, Ts, "InterSample", "zoh");
  dv = iddata (yv, uv, Ts, "InterSample", "zoh");
  M = srivc (iddata (y - mean (y), u - mean (u), Ts, "InterSample", "zoh"),
             nn);
  R = residtrace (d, M, "validation", dv, varargin{:});
endfunction

## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{M} =} back (@var{P}, @var{G}, @var{delay})
## A control-package model @var{G} (the result of c2d or d2c on the model
## struct @var{P}) as a model of @var{P}'s class (idproc: idtf), with the
## ny-by-nu @var{delay} (seconds or samples) and @var{P}'s names and noise
## variance.
## @end deftypefn

function M = back (P, G, delay)
  switch (P.kind)
    case "idpoly"
      M = idpoly (G);
      M = set (M, "InputDelay", delay(1, :).');
    case {"idtf", "idproc"}
      M = idtf (G);
      M = set (M, "IODelay", delay);
    case "idss"
      M = idss (G);
      M = set (M, "InputDelay", delay(1, :).');
  endswitch
  M = set (M, "NoiseVariance", P.NoiseVariance, "Name", P.Name,
           "InputName", P.InputName, "OutputName", P.OutputName);
endfunction

## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {} test_contsid_init_method ()
## Runs the inline tests of @file{octave/private/contsid_init_method.m},
## the start-method reader of the refined-IV family:
## @example
## octave --no-gui -q --eval \
##   "addpath tests/octave; test_contsid_init_method"
## @end example
## @end deftypefn

function test_contsid_init_method ()
  ctid_run_private_tests ("contsid_init_method.m");
endfunction

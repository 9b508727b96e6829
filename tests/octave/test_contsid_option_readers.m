## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {} test_contsid_option_readers ()
## Runs the inline tests of the private readers of the CONTSID options
## that several estimators share: @file{contsid_focus_option.m} (Focus:
## CONTSID's cut-off fc and Inf, the SITB's band and names) and
## @file{contsid_on_off.m} (Integration).  StepReduction is read by the
## core's table (core/include/ctid/offline/tfsrivc_options.hpp).
## @end deftypefn

function test_contsid_option_readers ()
  ctid_run_private_tests ("contsid_focus_option.m");
  ctid_run_private_tests ("contsid_on_off.m");
endfunction

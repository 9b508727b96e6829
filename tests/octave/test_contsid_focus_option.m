## -*- texinfo -*-
## @deftypefn {} {} test_contsid_focus_option ()
## Runs the inline tests of @file{octave/private/contsid_focus_option.m},
## the one reader of the estimators' @code{Focus} option (CONTSID's
## cut-off fc and Inf, the SITB's band and names).
## @end deftypefn

function test_contsid_focus_option ()
  ctid_run_private_tests ("contsid_focus_option.m");
endfunction

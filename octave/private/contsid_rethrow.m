## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {} contsid_rethrow (@var{err})
## Re-raises an error from a compiled gateway without the
## @qcode{"<name>_mex: "} prefix that Octave adds, keeping its identifier,
## so that the message starts with the public function name.
## @end deftypefn

function contsid_rethrow (err)
  msg = regexprep (err.message, '^[A-Za-z]\w*_mex: ', '');
  error (struct ("message", msg, "identifier", err.identifier,
                 "stack", err.stack));
endfunction

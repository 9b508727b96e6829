## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{root} =} ctid_test_root ()
## The repository root for the Octave tests: the environment variable
## CTID_ROOT (set by CTest, see tests/CMakeLists.txt), else two folders
## above this file (tests/octave/..).
## @end deftypefn

function root = ctid_test_root ()
  root = getenv ("CTID_ROOT");
  if (isempty (root))
    root = fileparts (fileparts (fileparts (mfilename ("fullpath"))));
  endif
endfunction

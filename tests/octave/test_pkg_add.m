## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {} test_pkg_add ()
## Tests of @file{octave/PKG_ADD}: adding the toolbox with @code{addpath}
## must leave its @code{iddata} constructor in front of the control
## package's, also after a later @code{pkg load control}, and must leave no
## variables behind.  Errors on the first failure, so that CTest can run it:
## @example
## octave --no-gui -q --eval "addpath ('tests/octave'); test_pkg_add"
## @end example
## @end deftypefn

function test_pkg_add ()
  here = fullfile (fileparts (fileparts (fileparts (mfilename ("fullpath")))),
                   "octave");
  ours = fullfile (here, "@iddata", "iddata.m");
  if (isempty (pkg ("list", "control")))
    addpath (here);
    assert (strcmp (which ("iddata"), ours));
    data = iddata ((1:5).', (1:5).', 1, "InterSample", "foh");
    assert (data.InterSample, "foh");
    printf ("test_pkg_add: control not installed, nothing to check\n");
    return;
  endif

  ## control installed, not loaded: addpath loads it behind this folder
  pkg unload control
  rmpath_if_present (here);
  before = evalin ("base", "who");
  addpath (here);
  assert (control_loaded ());
  assert (strcmp (which ("iddata"), ours));
  ## (evalin sets 'ans' in the base workspace itself)
  assert (isempty (setdiff (evalin ("base", "who"), [before; {"ans"}])));

  ## a later "pkg load control" leaves the path alone
  pkg load control
  assert (strcmp (which ("iddata"), ours));
  u = prbs (6);
  data = iddata (filter ([0, 0.5], [1, -0.5], u), u, 1, "InterSample", "foh");
  assert (data.InterSample, "foh");
  assert (isa (arx (data, 1), "tf"));

  ## control loaded first, toolbox added at the end: moved in front
  rmpath (here);
  addpath (here, "-end");
  assert (strcmp (which ("iddata"), ours));
  dirs = strsplit (path (), pathsep ());
  control_dir = fileparts (which ("moen4"));   # arx: the toolbox has one
  assert (find (strcmp (dirs, here)) < find (strcmp (dirs, control_dir)));
  printf ("test_pkg_add: all tests passed\n");
endfunction

function tf = control_loaded ()
  tf = any (cellfun (@(p) strcmp (p.name, "control") && p.loaded,
                     pkg ("list")));
endfunction

function rmpath_if_present (dir)
  if (any (strcmp (strsplit (path (), pathsep ()), dir)))
    rmpath (dir);
  endif
endfunction

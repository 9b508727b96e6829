## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {[@dots{}] =} contsid_call_shadowed (@var{dir}, @var{name}, @var{nout}, @var{args})
## Calls the function @var{name} defined in the folder @var{dir} (a
## control-package function that a toolbox function of the same name
## shadows on the path), with the arguments @var{args} and @var{nout}
## outputs: the toolbox folder leaves the path for the call (the path is
## restored after it, also on error), and the call is made from @var{dir}.
## @end deftypefn

function varargout = contsid_call_shadowed (dir, name, nout, args)
  old = pwd ();
  saved = path ();
  unwind_protect
    toolbox = fileparts (fileparts (mfilename ("fullpath")));
    rmpath (toolbox);
    cd (dir);
    [varargout{1:max (nout, 1)}] = feval (name, args{:});
  unwind_protect_cleanup
    path (saved);
    cd (old);
  end_unwind_protect
endfunction

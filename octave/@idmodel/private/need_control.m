## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {} need_control (@var{fname})
## Makes sure the control package is loaded, loading it when installed and
## putting this toolbox's folder back in front of it (see PKG_ADD); without
## the package: error @code{@var{fname}:notSupported}.
## @end deftypefn

function need_control (fname)
  if (any (cellfun (@(p) strcmp (p.name, "control") && p.loaded,
                    pkg ("list"))))
    return;
  endif
  try
    pkg load control
  catch
    error ([fname ":notSupported"],
           "%s: this method needs the control package (pkg install it)",
           fname);
  end_try_catch
  ## pkg load put control's folders first; this toolbox's iddata must stay
  ## in front of control's.
  addpath (fileparts (fileparts (fileparts (mfilename ("fullpath")))));
endfunction

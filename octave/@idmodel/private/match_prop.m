## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{name} =} match_prop (@var{M}, @var{key}, @var{fname})
## The canonical property name of @var{M} that @var{key} names: an exact
## match ignoring case, else a unique prefix (as the SITB accepts).
## Unknown or ambiguous names: error @code{@var{fname}:badInput}.
## @end deftypefn

function name = match_prop (M, key, fname)
  if (! ischar (key) || rows (key) != 1)
    error ([fname ":badInput"], "%s: property names must be strings", fname);
  endif
  names = model_props (M.kind);
  hit = strcmpi (key, names);
  if (! any (hit))
    hit = strncmpi (key, names, numel (key));
  endif
  ## "Intersample" style variants differ only in case; prefixes can clash
  ## only between distinct names.
  if (nnz (hit) != 1)
    if (any (hit))
      error ([fname ":badInput"],
             "%s: property name '%s' is ambiguous for %s (%s)", fname, key,
             M.kind, strjoin (names(hit), ", "));
    endif
    error ([fname ":badInput"], "%s: %s has no property '%s'", fname,
           M.kind, key);
  endif
  name = names{hit};
endfunction

## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {} check_subs (@var{s}, @var{cls})
## Checks the index structure @var{s} that @code{subsref}/@code{subsasgn}
## of class @var{cls} receive (as @code{substruct} builds it: a non-empty
## struct array with fields @code{type}, one of @qcode{"()"}, @qcode{"@{@}"}
## or @qcode{"."}, and @code{subs}, a name for @qcode{"."} and a cell of
## indices otherwise).  Anything else (a direct call with a malformed
## @var{s}): error @code{@var{cls}:badInput}.  Shared by the model classes
## and (linked into its private folder) @code{iddata}.
## @end deftypefn

function check_subs (s, cls)
  ok = (isstruct (s) && ! isempty (s) && isvector (s)
        && all (isfield (s, {"type", "subs"})));
  for k = 1:numel (s) * ok
    t = s(k).type;
    if (! (ischar (t) && any (strcmp (t, {"()", "{}", "."}))))
      ok = false;
    elseif (strcmp (t, "."))
      ok = ischar (s(k).subs) && rows (s(k).subs) == 1;
    else
      ok = iscell (s(k).subs);
    endif
    if (! ok)
      break;
    endif
  endfor
  if (! ok)
    error ([cls ":badInput"],
           "%s: the index must be a substruct (type '()', '{}' or '.')",
           cls);
  endif
endfunction

## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{opts} =} contsid_options (@var{fname}, @var{defs}, @
##   @var{args})
## Parse the name-value options of the front-end @var{fname}.
##
## @var{defs} is a scalar struct: its field names are the known options
## and its values the defaults.  @var{args} is a cell of name-value pairs
## (usually the tail of the front-end's @code{varargin}), a scalar struct of
## options, or a cell mixing both (each struct stands where a name would).
## Option names are matched against the fields of @var{defs} exactly
## but ignoring case; a later value overrides an earlier one.
##
## @var{opts} has every field of @var{defs}, with the values given in
## @var{args} in place of the defaults, plus @code{given_}: a row cell of
## the (canonical) names the user gave, in the order first given, so that
## front-ends can tell a default from a value the user chose.
##
## Errors, all with identifier @code{@var{fname}:badOption} and a message
## starting with @var{fname}: an unknown option name, a name that is not a
## string, a name without value, a struct array.
## @seealso{contsid_getdata}
## @end deftypefn

function opts = contsid_options (fname, defaults, args)
  if (nargin < 2 || ! (ischar (fname) && rows (fname) == 1))
    error ("contsid_options:badInput",
           "contsid_options: 'fname' must be the caller's name");
  endif
  if (nargin < 3)
    args = {};
  endif
  if (isstruct (defaults) && isscalar (defaults))
    names = fieldnames (defaults);
    lnames = lower (names);
  endif
  if (! (isstruct (defaults) && isscalar (defaults))
      || numel (unique (lnames)) != numel (lnames)
      || any (strcmp (lnames, "given_")))
    error ("contsid_options:badInput",
           ["contsid_options: 'defaults' must be a scalar struct whose ", ...
            "field names differ ignoring case, without 'given_'"]);
  endif
  if (isstruct (args))
    args = {args};
  elseif (! iscell (args))
    error ("contsid_options:badInput",
           "contsid_options: 'args' must be a cell or a struct");
  endif

  opts = defaults;
  given = cell (1, 0);
  k = 1;
  while (k <= numel (args))
    key = args{k};
    if (isstruct (key))
      if (! isscalar (key))
        error ([fname, ":badOption"],
               "%s: an options struct must be scalar, not %s", fname,
               mat2str (size (key)));
      endif
      fields = fieldnames (key);
      for j = 1:numel (fields)
        [opts, given] = assign (opts, given, fname, names, lnames,
                                fields{j}, key.(fields{j}));
      endfor
      k += 1;
      continue;
    endif
    if (! (ischar (key) && rows (key) == 1))
      error ([fname, ":badOption"],
             "%s: option name expected, but argument %d is a %s", fname, k,
             class (key));
    endif
    if (k == numel (args))
      error ([fname, ":badOption"],
             "%s: option '%s' has no value (options come in name-value pairs)",
             fname, key);
    endif
    [opts, given] = assign (opts, given, fname, names, lnames, key,
                            args{k+1});
    k += 2;
  endwhile
  opts.given_ = given;
endfunction

function [opts, given] = assign (opts, given, fname, names, lnames, key, val)
  idx = find (strcmp (lower (key), lnames));
  if (isempty (idx))
    error ([fname, ":badOption"], "%s: unknown option '%s' (known: %s)",
           fname, key, strjoin (names.', ", "));
  endif
  name = names{idx};
  opts.(name) = val;
  if (! any (strcmp (given, name)))
    given{end+1} = name;
  endif
endfunction

## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn  {} {} contsid_rethrow (@var{err})
## @deftypefnx {} {} contsid_rethrow (@var{err}, @var{fname})
## Re-raises the error @var{err} under the identifier
## @code{<fname>:<reason>} of the public function @var{fname}, so that an
## error raised by an inner call names the function the user called.
##
## The reason is kept: that of an identifier @code{<name>:<reason>} (an
## inner toolbox function's, a gateway's), that of one of Octave's own
## identifiers written as a word (@code{Octave:index-out-of-bounds} gives
## @code{<fname>:indexOutOfBounds}); an error without an identifier (the
## control package's, some of Octave's) gets the reason @code{failed}.
## The message starts with @var{fname} (the inner function's message
## follows it); the @qcode{"<name>_mex: "} prefix that Octave adds to a
## gateway's message is removed.  An error that already carries an
## identifier of @var{fname} (or of a name in the cell @var{fname}, such
## as a method's class) passes unchanged.  Without @var{fname} only the
## gateway prefix is removed.
## @end deftypefn

function contsid_rethrow (err, fname)
  msg = regexprep (err.message, '^[A-Za-z]\w*_mex: ', '');
  id = err.identifier;
  if (nargin > 1)
    own = cellstr (fname);
    tok = regexp (id, '^([A-Za-z]\w*):(.+)$', "tokens", "once");
    if (isempty (tok) || ! any (strcmp (tok{1}, own)))
      if (isempty (tok))
        reason = "failed";
      else
        ## a word: Octave's "index-out-of-bounds" becomes indexOutOfBounds
        words = regexp (tok{2}, '[A-Za-z0-9]+', "match");
        words(2:end) = cellfun (@(w) [upper(w(1)), w(2:end)],
                                words(2:end), "UniformOutput", false);
        reason = [words{:}];
        if (isempty (regexp (reason, '^[A-Za-z]\w*$', "once")))
          reason = "failed";
        endif
      endif
      id = [own{1} ":" reason];
      if (! strncmp (msg, [own{1} ":"], numel (own{1}) + 1))
        msg = [own{1} ": " msg];
      endif
    endif
  endif
  error (struct ("message", msg, "identifier", id, "stack", err.stack));
endfunction

%!error id=f:badInput
%! contsid_rethrow (struct ("message", "inner: bad", "identifier",
%!                          "inner:badInput", "stack", dbstack ()), "f");
%!error id=f:indexOutOfBounds
%! contsid_rethrow (struct ("message", "out of bound", "identifier",
%!                          "Octave:index-out-of-bounds", "stack",
%!                          dbstack ()), "f");
%!error id=f:failed
%! contsid_rethrow (struct ("message", "no id", "identifier", "",
%!                          "stack", dbstack ()), "f");
%!error id=idtf:badInput
%! contsid_rethrow (struct ("message", "idtf: own", "identifier",
%!                          "idtf:badInput", "stack", dbstack ()),
%!                  {"bode", "idtf"});
%!error id=f:badInput
%! contsid_rethrow (struct ("message", "f_mex: f: from the gateway",
%!                          "identifier", "f:badInput", "stack",
%!                          dbstack ()));
%!test
%! try
%!   contsid_rethrow (struct ("message", "inner: bad", "identifier",
%!                            "inner:badInput", "stack", dbstack ()), "f");
%! catch err
%!   assert (err.message, "f: inner: bad");
%! end_try_catch

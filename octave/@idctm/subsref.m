## -*- texinfo -*-
## @deftypefn {} {@var{v} =} subsref (@var{M}, @var{s})
## Read access to the properties of an @code{idctm} model: @code{M.B},
## @code{M.F}, @code{M.theta}, ... (see @code{help idctm}).
## @end deftypefn

function v = subsref (M, s)
  if (! strcmp (s(1).type, "."))
    error ("idctm:badInput", "idctm: use M.property to read a model");
  endif
  m = struct (M);
  if (! isfield (m, s(1).subs))
    error ("idctm:badInput", "idctm: no property '%s'", s(1).subs);
  endif
  v = m.(s(1).subs);
  if (numel (s) > 1)
    v = subsref (v, s(2:end));
  endif
endfunction

%!test
%! M = idctm ([1 2], [1 3 2]);
%! assert (M.B(2), 2);
%!error id=idctm:badInput subsref (idctm (1, [1 1]), struct ("type", "()", "subs", {{1}}))
%!error id=idctm:badInput subsref (idctm (1, [1 1]), struct ("type", ".", "subs", "nothing"))

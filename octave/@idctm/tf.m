## -*- texinfo -*-
## @deftypefn {} {@var{G} =} tf (@var{M})
## Converts an @code{idctm} model to a continuous-time @code{tf} of the
## control package (which must be installed; it is loaded if needed). The
## input delays nk become InputDelay = nk * Ts.
## @end deftypefn

function G = tf (M)
  if (! exist ("isct", "file"))
    try
      pkg load control
    catch
      error ("idctm:badInput", "idctm: tf needs the control package");
    end_try_catch
  endif
  m = struct (M);
  B = m.B;
  if (! iscell (B))
    B = {B};
  endif
  num = cellfun (@(b) b, B, "UniformOutput", false);
  den = repmat ({m.F}, 1, numel (B));
  ## Call the control package's constructor (not this method) with arrays.
  G = feval ("tf", num, den);
  if (any (m.nk) && ! isempty (m.Ts))
    G.inputdelay = m.nk(:) * m.Ts;
  endif
endfunction

%!test
%! pkg load control
%! G = tf (idctm (4, [1 2.4 4]));
%! assert (isa (G, "tf"));
%! [num, den] = tfdata (G, "vector");
%! assert (den, [1 2.4 4], 1e-14);
%! assert (num(end), 4, 1e-14);

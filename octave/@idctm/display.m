## -*- texinfo -*-
## @deftypefn {} {} display (@var{M})
## Shows an @code{idctm} model as B(p)/F(p) with its estimation method.
## @end deftypefn

function display (M)
  m = struct (M);
  B = m.B;
  if (! iscell (B))
    B = {B};
  endif
  printf ("%s = continuous-time model", inputname (1));
  if (! isempty (m.method))
    printf (" (%s)", m.method);
  endif
  printf ("\n");
  for j = 1:numel (B)
    printf ("  B%d(p) = %s\n", j, polystr (B{j}));
  endfor
  printf ("  F(p)  = %s\n", polystr (m.F));
  if (any (m.nk))
    printf ("  nk = %s\n", mat2str (m.nk));
  endif
endfunction

function s = polystr (c)
  n = numel (c) - 1;
  terms = {};
  for i = 1:numel (c)
    k = n - i + 1;
    if (k == 0)
      terms{end+1} = sprintf ("%.4g", c(i));
    elseif (k == 1)
      terms{end+1} = sprintf ("%.4g p", c(i));
    else
      terms{end+1} = sprintf ("%.4g p^%d", c(i), k);
    endif
  endfor
  s = strjoin (terms, " + ");
endfunction

%!test
%! M = idctm (4, [1 2.4 4]);
%! out = evalc ("display (M)");
%! assert (! isempty (strfind (out, "2.4 p")));

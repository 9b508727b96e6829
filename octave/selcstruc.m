## -*- texinfo -*-
## @deftypefn  {} {} selcstruc (@var{V})
## @deftypefnx {} {} selcstruc (@var{V}, @var{name}, @var{value}, @dots{})
## @deftypefnx {} {[@var{NN}, @var{Vcrit}] =} selcstruc (@dots{})
## Rank the structures tabulated by @code{srivcstruc} and show the best
## (CONTSID's structure selection).
##
## @var{V}: the matrix of @code{srivcstruc}, one row [RT2 YIC NN log(cond)
## N] per structure. Structures are ranked by the criterion
## @code{c2sort} (@qcode{"YIC"}, the default: the most negative first;
## or @qcode{"RT2"}: the largest first), among those with RT2 >=
## @code{RTeb} (default -Inf) and YIC <= @code{YICb} (default Inf);
## failed fits (NaN) come last and are not shown. Options:
## @table @code
## @item NberOfModels
## how many to display (default 10).
## @item c2sort (or c)
## @qcode{"YIC"} or @qcode{"RT2"}.
## @item RTeb, YICb
## bounds on RT2 and YIC.
## @end table
## CONTSID's FPEb, AICb and RTvb bound criteria that srivcstruc's V does
## not hold: error @code{selcstruc:notSupported} (with a validation set,
## RT2 is the validation figure: bound it with RTeb). @var{NN}'s columns
## may be those of one common denominator (2m + 1 for m inputs) or of one
## denominator per input (3m).
## Without output arguments the table is displayed, best first:
## structure, RT2, YIC, log10 cond. With outputs: @var{NN} the structures,
## best first (rows [nb nf nk]), and @var{Vcrit} their rows of @var{V}.
##
## @strong{Example}
## @example
## V = [0.95 -8.1 1 2 0 2.1 500; 0.80 -6.0 1 1 0 1.2 500];
## [NN, Vcrit] = selcstruc (V)
## @end example
## @seealso{srivcstruc, srivc}
## @end deftypefn

function [NN, Vcrit, varargout] = selcstruc (V, varargin)
  contsid_nargchk ("selcstruc", nargin, nargout, [0 Inf], 2);
  if (nargin < 1)
    error ("selcstruc:badInput", "selcstruc: expected the matrix V");
  endif
  ## NN: 2m + 1 columns (a common denominator) or 3m (one per input)
  w = columns (V) - 4;
  if (! isnumeric (V) || ! isreal (V) || ndims (V) > 2 || isempty (V)
      || w < 3 || (mod (w, 2) != 1 && mod (w, 3) != 0))
    error ("selcstruc:badInput",
           "selcstruc: V must be the matrix of srivcstruc, rows [RT2 YIC NN log(cond) N]");
  endif
  if (mod (numel (varargin), 2) != 0)
    error ("selcstruc:badOption",
           "selcstruc: options come as name-value pairs");
  endif
  count = 10; crit = "YIC"; rteb = -Inf; yicb = Inf;
  for i = 1:2:numel (varargin)
    name = varargin{i};
    value = varargin{i+1};
    if (! ischar (name))
      error ("selcstruc:badOption", "selcstruc: option names are strings");
    endif
    switch (lower (name))
      case "nberofmodels"
        if (! isnumeric (value) || ! isscalar (value) || value < 1
            || value != fix (value))
          error ("selcstruc:badOption",
                 "selcstruc: NberOfModels must be an integer >= 1");
        endif
        count = value;
      case {"c2sort", "c"}
        if (! ischar (value) || ! any (strcmpi (value, {"YIC", "RT2"})))
          error ("selcstruc:badOption",
                 "selcstruc: c2sort must be 'YIC' or 'RT2'");
        endif
        crit = upper (value);
      case "rteb"
        rteb = bound (value, "RTeb");
      case "yicb"
        yicb = bound (value, "YICb");
      case {"fpeb", "aicb", "rtvb"}
        ## CONTSID's bounds on criteria that srivcstruc's V does not hold
        error ("selcstruc:notSupported",
               ["selcstruc: '%s' bounds a criterion that srivcstruc's V ", ...
                "does not hold (its columns: RT2, YIC, NN, log10 cond, N; ", ...
                "RT2 is the validation figure when ZV is given: use RTeb)"],
               name);
      otherwise
        error ("selcstruc:badOption", "selcstruc: unknown option '%s'", name);
    endswitch
  endfor
  width = columns (V) - 4;               # the NN columns
  ok = isfinite (V(:, 1)) & isfinite (V(:, 2)) & V(:, 1) >= rteb ...
       & V(:, 2) <= yicb;
  rows_ok = find (ok);
  if (strcmp (crit, "YIC"))
    [~, order] = sortrows ([V(rows_ok, 2), -V(rows_ok, 1)]);
  else
    [~, order] = sortrows ([-V(rows_ok, 1), V(rows_ok, 2)]);
  endif
  best = rows_ok(order);
  Vcrit = V(best, :);
  NN = Vcrit(:, 3:2+width);
  if (nargout == 0)
    shown = min (count, rows (Vcrit));
    printf ("Structures ranked by %s (best first), %d of %d:\n", crit,
            shown, rows (V));
    printf ("  %-18s %9s %9s %11s\n", "[nb nf nk]", "RT2", "YIC",
            "log10 cond");
    for k = 1:shown
      printf ("  %-18s %9.4f %9.3f %11.2f\n", mat2str (NN(k, :)),
              Vcrit(k, 1), Vcrit(k, 2), Vcrit(k, end-1));
    endfor
    if (rows (Vcrit) < rows (V))
      printf ("  (%d structure(s) failed or fell outside the bounds)\n",
              rows (V) - rows (Vcrit));
    endif
    clear NN Vcrit
  endif
endfunction

function v = bound (v, name)
  if (! isnumeric (v) || ! isreal (v) || ! isscalar (v) || isnan (v))
    error ("selcstruc:badOption", "selcstruc: %s must be a real scalar", name);
  endif
endfunction

%!shared V
%! V = [0.95 -8.1 1 2 0 2.1 500
%!      0.80 -6.0 1 1 0 1.2 500
%!      0.96 -5.0 2 3 0 4.0 500
%!      NaN  NaN  3 3 0 NaN 500];

%!test  # YIC: most negative first; failed fits dropped
%! [NN, Vc] = selcstruc (V);
%! assert (NN, [1 2 0; 1 1 0; 2 3 0]);
%! assert (Vc(:, 2)', [-8.1 -6.0 -5.0]);

%!test  # RT2 ranking and a bound on RT2
%! NN = selcstruc (V, "c2sort", "RT2");
%! assert (NN(1, :), [2 3 0]);
%! NN = selcstruc (V, "RTeb", 0.9);
%! assert (NN, [1 2 0; 2 3 0]);

%!test  # display without outputs
%! out = evalc ("selcstruc (V, 'NberOfModels', 2)");
%! assert (! isempty (strfind (out, "[1 2 0]")));
%! assert (isempty (strfind (out, "[2 3 0]")));

%!error id=selcstruc:badInput selcstruc ()
%!test  # two inputs, one denominator each: NN of 3m = 6 columns
%! W = [0.95 -8 1 2 2 1 0 0 2.1 500; 0.80 -6 1 1 1 1 0 0 1.2 500];
%! [NN, Vc] = selcstruc (W, "c2sort", "RT2");
%! assert (NN, [1 2 2 1 0 0; 1 1 1 1 0 0]);
%! assert (Vc(:, 1), [0.95; 0.80]);
%!error id=selcstruc:badInput selcstruc ([1 2 3])
%!error id=selcstruc:badInput selcstruc ([0.9 -8 1 2 0 0 1 500])
%!error id=selcstruc:badOption selcstruc (V, "NberOfModels")
%!error id=selcstruc:badOption selcstruc (V, "NberOfModels", 0)
%!error id=selcstruc:badOption selcstruc (V, "c2sort", "AIC")
%!error id=selcstruc:badOption selcstruc (V, "RTeb", "x")
%!error id=selcstruc:badOption selcstruc (V, "bogus", 1)
%!error id=selcstruc:notSupported selcstruc (V, "FPEb", 1)
%!error id=selcstruc:notSupported selcstruc (V, "RTvb", 0.5)

%!demo
%! V = [0.95 -8.1 1 2 0 2.1 500; 0.80 -6.0 1 1 0 1.2 500];
%! selcstruc (V)
%! [NN, Vcrit] = selcstruc (V)

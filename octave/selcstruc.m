## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

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
## how many to display (default 5, as CONTSID; @qcode{"all"}).
## @item c2sort
## @qcode{"YIC"}, @qcode{"RT2"} (also CONTSID's @qcode{"RTe"} and
## @qcode{"RTv"}: V holds one R_T^2, on ZV when srivcstruc was given one,
## else on ZE) or @qcode{"np"} (fewest parameters first, then YIC).
## @item c
## CONTSID's further criteria to display (a name or a cell): the R_T^2 of
## V is always shown.
## @item RTeb, YICb
## bounds on RT2 and YIC.
## @end table
## CONTSID's FPE and AIC (in c2sort, c, FPEb, AICb) and RTvb are criteria
## that srivcstruc's V does not hold: error @code{selcstruc:notSupported}
## (with a validation set, RT2 is the validation figure: bound it with
## RTeb). @var{NN}'s columns
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

function varargout = selcstruc (varargin)
  varargout = contsid_guard ("selcstruc", @selcstruc_body, nargout, varargin);
endfunction

function [NN, Vcrit, varargout] = selcstruc_body (V, varargin)
  contsid_nargchk ("selcstruc", nargin, nargout, [0 Inf], 2);
  if (nargin < 1)
    error ("selcstruc:badInput", "selcstruc: expected the matrix V");
  endif
  ## NN: 2m + 1 columns (a common denominator) or 3m (one per input)
  width = columns (V) - 4;               # the NN columns
  if (! isnumeric (V) || ! isreal (V) || ndims (V) > 2 || isempty (V)
      || width < 3 || (mod (width, 2) != 1 && mod (width, 3) != 0))
    error ("selcstruc:badInput",
           "selcstruc: V must be the matrix of srivcstruc, rows [RT2 YIC NN log(cond) N]");
  endif
  if (mod (numel (varargin), 2) != 0)
    error ("selcstruc:badOption",
           "selcstruc: options come as name-value pairs");
  endif
  count = 5; crit = "YIC"; rteb = -Inf; yicb = Inf;
  for i = 1:2:numel (varargin)
    name = varargin{i};
    value = varargin{i+1};
    if (! ischar (name))
      error ("selcstruc:badOption", "selcstruc: option names are strings");
    endif
    switch (lower (name))
      case "nberofmodels"
        if (ischar (value) && strcmpi (value, "all"))
          value = Inf;
        elseif (! isnumeric (value) || ! isscalar (value) || value < 1
                || value != fix (value))
          error ("selcstruc:badOption",
                 "selcstruc: NberOfModels must be an integer >= 1 or 'all'");
        endif
        count = value;
      case "c2sort"
        crit = criterion (value, {"YIC", "RT2", "RTE", "RTV", "NP"});
        if (any (strcmp (crit, {"RTE", "RTV"})))
          crit = "RT2";                    # the one R_T^2 that V holds
        endif
      case "c"
        ## CONTSID: further criteria to display; V holds R_T^2 (shown)
        cs = value;
        if (! iscell (cs))
          cs = {cs};
        endif
        for k = 1:numel (cs)
          criterion (cs{k}, {"RTE", "RTV", "RT2", "YIC"});
        endfor
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
  ok = isfinite (V(:, 1)) & isfinite (V(:, 2)) & V(:, 1) >= rteb ...
       & V(:, 2) <= yicb;
  rows_ok = find (ok);
  switch (crit)
    case "YIC"
      [~, order] = sortrows ([V(rows_ok, 2), -V(rows_ok, 1)]);
    case "RT2"
      [~, order] = sortrows ([-V(rows_ok, 1), V(rows_ok, 2)]);
    case "NP"
      ## the number of parameters: the nb and nf entries, not the m delays
      ## (2m + 1 columns for a common denominator, else 3m; 9 columns are
      ## read as the former)
      m = merge (mod (width, 2) == 1, (width - 1) / 2, width / 3);
      np = sum (V(rows_ok, 3:2+width-m), 2);
      [~, order] = sortrows ([np, V(rows_ok, 2)]);
  endswitch
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

## A criterion name of CONTSID's selcstruc, upper case; those V does not
## hold (FPE, AIC) are selcstruc:notSupported.
function c = criterion (v, allowed)
  if (! ischar (v))
    error ("selcstruc:badOption", "selcstruc: a criterion is a name");
  endif
  c = upper (v);
  if (any (strcmp (c, {"FPE", "AIC"})))
    error ("selcstruc:notSupported",
           ["selcstruc: %s is not a column of srivcstruc's V (RT2, YIC, ", ...
            "NN, log10 cond, N)"], v);
  endif
  if (! any (strcmp (c, allowed)))
    error ("selcstruc:badOption", "selcstruc: criterion '%s' (one of %s)",
           v, strjoin (allowed, ", "));
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
%!error id=selcstruc:badOption selcstruc (V, "RTeb", "x")
%!error id=selcstruc:badOption selcstruc (V, "bogus", 1)
%!error id=selcstruc:notSupported selcstruc (V, "FPEb", 1)
%!error id=selcstruc:notSupported selcstruc (V, "c2sort", "AIC")
%!error id=selcstruc:notSupported selcstruc (V, "c", {"RTv", "FPE"})
%!error id=selcstruc:badOption selcstruc (V, "c2sort", "bogus")
%!error id=selcstruc:badOption selcstruc (V, "NberOfModels", "some")
%!test  # c2sort 'np': fewest parameters first (nb + nf), then YIC; RTe
%! ## and RTv sort by V's R_T^2; 'c' RTv and NberOfModels 'all' accepted
%! NN = selcstruc (V, "c2sort", "np");
%! np = sum (NN(:, 1:2), 2);
%! assert (issorted (np));
%! assert (selcstruc (V, "c2sort", "RTv"), selcstruc (V, "c2sort", "RT2"));
%! assert (selcstruc (V, "c2sort", "RTe"), selcstruc (V, "c2sort", "RT2"));
%! assert (selcstruc (V, "c", "RTv", "NberOfModels", "all"), selcstruc (V));
%! W = [0.95 -8 1 2 2 1 0 0 2.1 500; 0.80 -6 1 1 1 1 0 0 1.2 500];
%! assert (selcstruc (W, "c2sort", "np"), [1 1 1 1 0 0; 1 2 2 1 0 0]);
%!error id=selcstruc:notSupported selcstruc (V, "RTvb", 0.5)

%!demo
%! V = [0.95 -8.1 1 2 0 2.1 500; 0.80 -6.0 1 1 0 1.2 500];
%! selcstruc (V)
%! [NN, Vcrit] = selcstruc (V)

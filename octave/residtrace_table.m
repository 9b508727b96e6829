## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn  {} {@var{md} =} residtrace_table (@var{R})
## @deftypefnx {} {@var{md} =} residtrace_table (@var{R}, @var{file})
## The before/after table of a @code{residtrace} result @var{R} as
## Markdown: one row per model (as given, re-estimated, then each added
## effect) with the validation RMSE of the output simulated from the
## input (plus an estimated initial state where 'initial_state' was
## added) and, in its own column, the RMSE of a simulation with tracked
## parameters or of a one-step prediction (drift, coloured noise, which
## use the validation output),
## the fit (%), the p-values of the residual's whiteness (Ljung-Box) and
## of its independence from the input; what was done about the record's
## levels; the ranking of the first pass with each candidate's group
## (simulated ones and those using the validation output are ranked
## apart), score, p-value and evidence; a line for each further
## pass (what it added, its best scores); and the physical parameters
## before and after. Written to @var{file} when given; printed
## when no output is asked.
##
## @strong{Example}
## @example
## Ts = 0.05; u = prbs (10, 6); N = numel (u);
## y = simc (idctm (2, [1 1.2 1]), u + 0.4, Ts) + 0.05 * randn (N, 1);
## R = residtrace (iddata (y, u, Ts), srivc (iddata (y, u, Ts), [1 2 0]));
## residtrace_table (R)
## @end example
## @seealso{residtrace}
## @end deftypefn

function varargout = residtrace_table (varargin)
  varargout = contsid_guard ("residtrace_table", @residtrace_table_body,
                             nargout, varargin);
endfunction

function [md, varargout] = residtrace_table_body (R, file, varargin)
  contsid_nargchk ("residtrace_table", nargin, nargout, [1 2], 1);
  if (nargin < 1 || ! isstruct (R) || ! isfield (R, "steps"))
    error ("residtrace_table:badInput",
           "residtrace_table: R must be the result of residtrace");
  endif
  try
    md = markdown (R);
  catch err
    ## A damaged or partial result: say so under this function's name.
    error ("residtrace_table:badInput",
           "residtrace_table: R is not a complete residtrace result (%s)",
           err.message);
  end_try_catch
  if (nargin > 1)
    if (! (ischar (file) && rows (file) == 1))
      error ("residtrace_table:badInput",
             "residtrace_table: FILE must be a file name");
    endif
    fid = fopen (file, "w");
    if (fid < 0)
      error ("residtrace_table:badInput",
             "residtrace_table: cannot write '%s'", file);
    endif
    fputs (fid, md);
    fclose (fid);
  endif
  if (nargout == 0 && nargin < 2)
    printf ("%s", md);
    clear md;
  endif
endfunction

## The report of R as markdown text.
function md = markdown (R)
  L = {};
  L{end+1} = sprintf ("Effect found: **%s**", R.effect);
  if (! R.testable)
    L{end+1} = sprintf ("Cannot test: %s.", R.reason);
  endif
  if (isfield (R, "levels") && ! isempty (R.levels.text))
    L{end+1} = sprintf ("Levels: %s.", R.levels.text);
  endif
  if ((isfield (R, "initial_state") && isequal (R.initial_state, true))
      || any (strcmp (R.effects, "initial_state")))
    L{end+1} = ["Simulations after 'initial_state' include the free ", ...
                "response from an initial state fitted on each record."];
  endif
  L{end+1} = "";
  L{end+1} = ["| model | validation RMSE, simulation | validation RMSE, ", ...
              "tracked or predicted | fit (%) | whiteness p ", ...
              "| independence p |"];
  L{end+1} = "|---|---|---|---|---|---|";
  for k = 1:numel (R.steps)
    s = R.steps(k);
    other = "-";
    if (isfield (s, "rmse_other") && ! isnan (s.rmse_other))
      other = sprintf ("%s (%s)", num (s.rmse_other), s.kind);
    endif
    L{end+1} = sprintf ("| %s | %s | %s | %s | %s | %s |", s.label,
                        num (s.rmse), other, num (s.fit, "%.2f"),
                        num (s.white_p, "%.2g"), num (s.indep_p, "%.2g"));
  endfor
  if (! isempty (R.ranking))
    L{end+1} = "";
    L{end+1} = ["| candidate (first pass) | ranked among | score | p ", ...
                "| significant | variant | evidence |"];
    L{end+1} = "|---|---|---|---|---|---|---|";
    for k = 1:numel (R.ranking)
      r = R.ranking(k);
      grp = "";
      if (isfield (r, "group"))
        grp = r.group;
      endif
      if (r.applicable)
        ev = "";
        if (isfield (r.evidence, "text"))
          ev = r.evidence.text;
        endif
        L{end+1} = sprintf ("| %s | %s | %s | %s | %s | %s | %s |",
                            r.effect, grp,
                            num (r.score, "%.4g"), num (r.p, "%.2g"),
                            yesno (r.significant), r.variant,
                            strrep (ev, "|", "/"));
      else
        L{end+1} = sprintf ("| %s | %s | - | - | no | not tested | %s |",
                            r.effect, grp, r.reason);
      endif
    endfor
  endif
  if (isfield (R, "history") && numel (R.history) > 1)
    L{end+1} = "";
    for k = 2:numel (R.history)
      h = R.history(k);
      top = {};
      for i = 1:min (3, numel (h.ranking))
        r = h.ranking(i);
        if (r.applicable)
          top{end+1} = sprintf ("%s %.3g (p %.2g)", r.effect, r.score, r.p);
        endif
      endfor
      L{end+1} = sprintf ("Pass %d: %s; best scores: %s.", k,
                          ifelse_ (strcmp (h.effect, "none"),
                                   "nothing significant",
                                   ["added " h.effect]),
                          strjoin (top, ", "));
    endfor
  endif
  L{end+1} = "";
  first = R.steps(1).params;
  last = R.steps(end).params;
  names = unique_stable ([{first.name}, {last.name}]);
  L{end+1} = sprintf ("| parameter | %s | %s |", R.steps(1).label,
                      R.steps(end).label);
  L{end+1} = "|---|---|---|";
  for k = 1:numel (names)
    L{end+1} = sprintf ("| %s | %s | %s |", names{k}, pval (first, names{k}),
                        pval (last, names{k}));
  endfor
  md = strjoin (L, "\n");
  md = [md "\n"];
endfunction

function s = num (v, f)
  if (nargin < 2)
    f = "%.4g";
  endif
  if (isempty (v) || (isnumeric (v) && any (isnan (v))))
    s = "-";
  else
    s = sprintf (f, v);
  endif
endfunction

function s = ifelse_ (c, a, b)
  if (c)
    s = a;
  else
    s = b;
  endif
endfunction

function s = yesno (b)
  if (b)
    s = "yes";
  else
    s = "no";
  endif
endfunction

function c = unique_stable (c)
  [~, i] = unique (c, "first");
  c = c(sort (i));
endfunction

## value (+- std) of the named parameter(s); repeated names (poles, zeros)
## are listed together
function s = pval (p, name)
  k = find (strcmp ({p.name}, name));
  if (isempty (k))
    s = "-";
    return;
  endif
  parts = {};
  for i = k
    v = p(i).value;
    if (numel (v) > 1)
      t = ["[" strjoin(arrayfun (@(x) sprintf ("%.4g", x), real (v(:).'),
                                 "UniformOutput", false), ", ") "]"];
    elseif (iscomplex (v) && imag (v) != 0)
      t = sprintf ("%.4g%+.4gi", real (v), imag (v));
    else
      t = sprintf ("%.4g", real (v));
    endif
    if (isscalar (p(i).std) && isfinite (p(i).std))
      t = sprintf ("%s ± %.2g", t, p(i).std);
    endif
    parts{end+1} = t;
  endfor
  s = strjoin (parts, ", ");
endfunction

%!shared R
%! randn ("state", 21);
%! Ts = 0.05; u = prbs (9, 4); N = numel (u); G = idctm (2, [1 1.2 1]);
%! y = simc (G, u - 0.2, Ts) + 0.05 * randn (N, 1);
%! R = residtrace (iddata (y, u, Ts), srivc (iddata (y, u, Ts), [1 2 0]),
%!                 "effects", {"offset", "delay"});

%!test  # one row per model, the ranking, the parameters before and after
%! md = residtrace_table (R);
%! L = strsplit (md, "\n");
%! assert (any (strncmp (L, "| M as given |", 14)));
%! assert (any (strncmp (L, "| + offset (", 12)));
%! assert (any (strncmp (L, "| delay |", 9)));
%! row = L{strncmp (L, "| input offset b_c/b0 |", 23)};
%! assert (! isempty (strfind (row, "| - |")));   # absent before
%! v = str2double (regexp (row, '\| (-?[0-9.]+) ±', "tokens", "once"){1});
%! assert (v, -0.2, 0.02);

%!test  # written to a file, identical to the returned text
%! f = [tempname() ".md"];
%! md = residtrace_table (R, f);
%! assert (fileread (f), md);
%! delete (f);

%!error id=residtrace_table:badInput residtrace_table (struct ("a", 1))
%!error <not a complete> residtrace_table (struct ("steps", 1, "effect", "x"))
%!error id=residtrace_table:badInput residtrace_table (struct ("steps", 1), 5)
%!error id=residtrace_table:badInput residtrace_table (R, "/nonexistent/dir/x.md")

%!demo
%! Ts = 0.05; u = prbs (9, 4); N = numel (u);
%! y = simc (idctm (2, [1 1.2 1]), u + 0.3, Ts) + 0.05 * randn (N, 1);
%! R = residtrace (iddata (y, u, Ts), srivc (iddata (y, u, Ts), [1 2 0]));
%! residtrace_table (R)

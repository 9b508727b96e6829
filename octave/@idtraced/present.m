## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn  {} {} present (@var{M})
## @deftypefnx {} {@var{txt} =} present (@var{M})
## Shows a model @code{residtrace} returned: the effects it added, its
## linear part (@code{M.linear}, with the standard deviations of its
## coefficients), the physical parameters (@code{M.params}: gains, time
## constants, each effect in physical units) as value +/- one standard
## deviation (none where the fit gives none), the levels (the input level
## removed from the input, the output level) and how it is simulated.
## With an output, returns the text instead.
##
## @strong{Example}
## @example
## Ts = 0.05; u = prbs (9, 4); N = numel (u); G = idctm (2, [1 1.2 1]);
## y = simc (G, u + 0.3, Ts) + 0.03 * randn (N, 1);
## R = residtrace (iddata (y, u, Ts), G, "effects", @{"offset"@});
## present (R.final_model)
## @end example
## @seealso{idtraced, residtrace}
## @end deftypefn

function varargout = present (varargin)
  varargout = contsid_guard ({"present", "idtraced"}, @present_body, nargout,
                             varargin);
endfunction

function [txt, varargout] = present_body (M, varargin)
  contsid_nargchk ("present", nargin, nargout, [1 1], 1);
  m = struct (M).model;
  if (! isfield (m, "linear"))
    s = "empty residtrace model (idtraced)\n";
  else
    s = model_text (m);
  endif
  if (nargout > 0)
    txt = s;
  else
    printf ("%s", s);
  endif
endfunction

function s = model_text (m)
  eff = {};
  if (isfield (m, "effects"))
    eff = m.effects;
  endif
  if (isempty (eff))
    s = "Continuous-time model from residtrace, no effect added\n";
  else
    s = sprintf ("Continuous-time model from residtrace, effects added: %s\n",
                 strjoin (eff, ", "));
  endif
  lin = present (m.linear);
  lin = regexprep (lin, '^[^\n]*=\s*\n', "", "once");   # its name line
  s = [s "\nLinear part (M.linear):\n" indent(lin)];
  if (numel (m.channels) > 1)
    ch = m.channels;
    s = [s sprintf("  its inputs: %s\n",
                   strjoin (arrayfun (@channel_text, ch, "UniformOutput",
                                      false), ", "))];
  endif
  s = [s "\nPhysical parameters (M.params, value +/- standard deviation):\n"];
  p = m.params;
  if (isempty (p))
    s = [s "  none\n"];
  endif
  w = max ([cellfun(@numel, {p.name}), 10]);
  for k = 1:numel (p)
    s = [s sprintf("  %-*s  %s\n", w, p(k).name, value_text (p(k)))];
  endfor
  s = [s "\n" levels_text(m) simulation_text(m)];
endfunction

function s = channel_text (c)
  s = c.type;
  if (isfield (c, "name") && ! isempty (c.name))
    s = c.name;
  endif
endfunction

function s = value_text (p)
  v = p.value;
  sd = p.std;
  if (isempty (v))
    s = "-";
    return;
  endif
  if (! isreal (v))
    s = num2str (v, 5);
  elseif (isscalar (v))
    s = sprintf ("%.5g", v);
  else
    s = ["[" strjoin(arrayfun (@(x) sprintf ("%.5g", x), v(:).',
                               "UniformOutput", false), " ") "]"];
  endif
  sd = sd(isfinite (sd));
  if (! isempty (sd) && isreal (sd))
    if (isscalar (sd))
      s = [s sprintf(" +/- %.2g", sd)];
    else
      s = [s " +/- [" strjoin(arrayfun (@(x) sprintf ("%.2g", x), sd(:).',
                                        "UniformOutput", false), " ") "]"];
    endif
  endif
endfunction

function s = levels_text (m)
  u0 = m.u0(:).';
  s = sprintf ("Levels: input level u0 = %s removed from the input",
               strjoin (arrayfun (@(x) sprintf ("%.5g", x), u0,
                                  "UniformOutput", false), ", "));
  c = [];
  for k = 1:numel (m.out)
    if (strcmp (m.out(k).type, "offset"))
      c = m.out(k);
    endif
  endfor
  if (! isempty (c))
    lev = struct ("value", c.c(1), "std", c.cstd(1));
    s = [s "; output level " value_text(lev)];
  elseif (isfield (m, "phys") && isstruct (m.phys) && isfield (m.phys, "c"))
    s = [s sprintf("; output level %.5g (of the physical realisation)",
                   m.phys.c)];
  else
    s = [s "; no output level"];
  endif
  s = [s "\n"];
endfunction

function s = simulation_text (m)
  s = sprintf ("Simulated: from rest, Ts = %g s", m.Ts);
  if (isfield (m, "x0") && m.x0)
    s = [s ", plus an initial state fitted on each record"];
  endif
  if (isfield (m, "phys") && ! isempty (m.phys))
    s = [s sprintf(", as a physical realisation (%s)", m.phys.kind)];
  endif
  if (m.npre > 0)
    s = [s sprintf(", scored on the samples after the first %d", m.npre)];
  endif
  s = [s "\n"];
endfunction

function s = indent (t)
  L = strsplit (t, "\n", "CollapseDelimiters", false);
  if (isempty (L{end}))
    L(end) = [];
  endif
  full = ! cellfun (@isempty, L);
  L(full) = strcat ({"  "}, L(full));
  s = [strjoin(L, "\n") "\n"];
endfunction

%!test  # every part is shown: effects, linear part, parameters, levels
%! s = struct ("F", [1 1], "channels", struct ("type", "input", "name", "u1",
%!                                             "B", 2),
%!             "out", struct ("type", "offset", "c", 20, "cstd", 0.1,
%!                            "omega", 0),
%!             "u0", 5, "Ts", 0.1, "npre", 0, "substeps", 10,
%!             "closed_loop", false, "effects", {{"offset"}},
%!             "params", struct ("name", {"static gain", "output offset"},
%!                               "value", {2, 20}, "std", {NaN, 0.1}),
%!             "linear", idctm (2, [1 1]), "phys", [], "x0", false);
%! t = present (idtraced (s));
%! assert (! isempty (strfind (t, "effects added: offset")));
%! assert (! isempty (strfind (t, "Linear part (M.linear)")));
%! assert (! isempty (regexp (t, 'static gain\s+2\n')));
%! assert (! isempty (regexp (t, 'output offset\s+20 \+/- 0.1\n')));
%! assert (! isempty (strfind (t, "input level u0 = 5")));
%! assert (! isempty (strfind (t, "output level 20 +/- 0.1")));
%! out = evalc ("present (idtraced (s))");
%! assert (out, t);
%! assert (! isempty (strfind (present (idtraced ()), "empty")));

%!error id=present:badInput present (idtraced (), 1)
%!error id=present:badInput [a, b] = present (idtraced ())

## SPDX-License-Identifier: BSD-3-Clause
## Copyright (C) the ctid authors

## -*- texinfo -*-
## @deftypefn  {} {} make_reference ()
## @deftypefnx {} {} make_reference (@var{outdir})
## @deftypefnx {} {@var{problems} =} make_reference (@dots{})
## Write the function reference of the toolbox as Markdown: one page per
## public function (@file{octave/*.m}), one page per class
## (@file{octave/@@@var{class}/}, the constructor and every method), and
## @file{index.md}, ordered by the categories of the repository's
## @file{INDEX} file.  The default @var{outdir} is @file{doc/reference}.
##
## The help texts are read with @code{get_help_text} and their texinfo is
## converted to Markdown here (deftypefn signatures, @@table, @@itemize,
## @@enumerate, @@example, @@seealso and the inline commands).
##
## It checks, and raises the error @code{make_reference:incomplete} after
## writing the pages when one check fails:
## @itemize
## @item every public function and method has a help text;
## @item every one has an example: an @@example block in its help text or
## a @code{%!demo} block in its file;
## @item @file{INDEX} lists every public function and every class (a
## folder @file{@@@var{class}} with a constructor @file{@var{class}.m};
## @file{@@double} only adds methods to a built-in class), and nothing
## else.
## @end itemize
##
## @example
## octave-cli --eval "addpath doc; make_reference ('build/doc/reference')"
## @end example
## @end deftypefn

function problems = make_reference (outdir)
  root = fileparts (fileparts (mfilename ("fullpath")));
  if (nargin < 1 || isempty (outdir))
    outdir = fullfile (root, "doc", "reference");
  endif
  src = fullfile (root, "octave");

  ## The public surface.
  funcs = sort (strrep (cellfun (@(f) fname (f), glob (fullfile (src, "*.m")),
                                 "UniformOutput", false), ".m", ""));
  cdirs = glob (fullfile (src, "@*"));
  classes = struct ("name", {}, "ctor", {}, "methods", {});
  for k = 1:numel (cdirs)
    name = fname (cdirs{k})(2:end);
    files = glob (fullfile (cdirs{k}, "*.m"));
    meths = sort (strrep (cellfun (@(f) fname (f), files,
                                   "UniformOutput", false), ".m", ""));
    isctor = strcmp (meths, name);
    classes(end+1) = struct ("name", name, "ctor", any (isctor),
                             "methods", {meths(! isctor)});
  endfor

  problems = {};
  pages = [funcs(:); strcat("class-", {classes.name})'];

  ## INDEX: categories and the names under them.
  [cats, index_problems] = read_index (fullfile (root, "INDEX"), funcs,
                                       classes);
  problems = [problems, index_problems];

  if (! exist (outdir, "dir"))
    [ok, msg] = mkdir (outdir);
    if (! ok)
      error ("make_reference:badInput", "make_reference: %s: %s", outdir, msg);
    endif
  endif
  old = glob (fullfile (outdir, "*.md"));
  for k = 1:numel (old)
    delete (old{k});
  endfor

  ## Function pages.
  summaries = struct ();
  for k = 1:numel (funcs)
    file = fullfile (src, [funcs{k} ".m"]);
    [md, summary, p] = help_page (file, funcs{k}, pages);
    problems = [problems, p];
    summaries.(funcs{k}) = summary;
    write_page (fullfile (outdir, [funcs{k} ".md"]),
                {["# " funcs{k}], "", md});
  endfor

  ## Class pages: constructor, then the methods.
  for k = 1:numel (classes)
    c = classes(k);
    cdir = fullfile (src, ["@" c.name]);
    body = {};
    summary = "";
    if (c.ctor)
      [md, summary, p] = help_page (fullfile (cdir, [c.name ".m"]),
                                    ["@" c.name "/" c.name], pages,
                                    c.methods);
      problems = [problems, p];
      body = {md};
      title = sprintf ("# %s (class)", c.name);
    else
      title = sprintf ("# Methods of the built-in class %s", c.name);
      summary = sprintf ("methods for numeric (%s) arguments", c.name);
    endif
    parent = parent_class (cdir, c);
    if (! isempty (parent))
      body(end+1:end+2) = {"", sprintf(["The methods of [%s](class-%s.md) " ...
                                         "apply to it as well."],
                                        parent, parent)};
    endif
    if (! isempty (c.methods))
      body(end+1:end+2) = {"", "## Methods"};
      body{end+1} = "";
      body{end+1} = strjoin (cellfun (@(m) sprintf ("[%s](#%s)", m,
                                                    lower (m)),
                                      c.methods, "UniformOutput", false),
                             " · ");
      for j = 1:numel (c.methods)
        m = c.methods{j};
        [md, ~, p] = help_page (fullfile (cdir, [m ".m"]),
                                ["@" c.name "/" m], pages, c.methods);
        problems = [problems, p];
        body(end+1:end+4) = {"", ["### " m], "", md};
      endfor
    endif
    summaries.(["class_" c.name]) = summary;
    write_page (fullfile (outdir, ["class-" c.name ".md"]), [{title, ""}, body]);
  endfor

  ## index.md by the categories of INDEX.
  lines = {"# Function reference", "", ...
           ["Generated by `doc/make_reference.m` from the help texts " ...
            "(`help NAME` in Octave shows the same text). The categories " ...
            "are those of the package's `INDEX`."], ""};
  for k = 1:numel (cats)
    lines(end+1:end+2) = {["## " cats(k).title], ""};
    lines(end+1:end+2) = {"| name | summary |", "|---|---|"};
    for j = 1:numel (cats(k).names)
      n = cats(k).names{j};
      if (any (strcmp (n, funcs)))
        link = sprintf ("[`%s`](%s.md)", n, n);
        s = summaries.(n);
      elseif (any (strcmp (n, {classes.name})))
        link = sprintf ("[`%s`](class-%s.md) (class)", n, n);
        s = summaries.(["class_" n]);
      else
        continue;
      endif
      lines{end+1} = sprintf ("| %s | %s |", link, strrep (s, "|", "\\|"));
    endfor
    lines{end+1} = "";
  endfor
  extra = classes(! [classes.ctor]);
  if (! isempty (extra))
    lines(end+1:end+2) = {"## Methods for built-in classes", ""};
    for k = 1:numel (extra)
      lines{end+1} = sprintf ("- [%s](class-%s.md): %s", extra(k).name,
                              extra(k).name, strjoin (extra(k).methods, ", "));
    endfor
  endif
  write_page (fullfile (outdir, "index.md"), lines);

  if (! isempty (problems))
    fprintf (stderr, "make_reference: %s\n", problems{:});
    error ("make_reference:incomplete",
           "make_reference: %d problem(s) in the help texts or INDEX",
           numel (problems));
  endif
  printf ("make_reference: %d functions, %d classes written to %s\n",
          numel (funcs), numel (classes), outdir);
  if (nargout == 0)
    clear problems;
  endif
endfunction

function n = fname (f)
  [~, n, e] = fileparts (f);
  n = [n e];
endfunction

## The parent class named in the constructor's call to class ().
function parent = parent_class (cdir, c)
  parent = "";
  if (! c.ctor)
    return;
  endif
  txt = fileread (fullfile (cdir, [c.name ".m"]));
  tok = regexp (txt, ['class \(struct \(\), "' c.name '",\s*(\w+) \('],
                "tokens", "once");
  if (! isempty (tok))
    parent = tok{1};
  endif
endfunction

function [cats, problems] = read_index (file, funcs, classes)
  problems = {};
  cats = struct ("title", {}, "names", {});
  if (! exist (file, "file"))
    problems{end+1} = "INDEX: file missing";
    return;
  endif
  L = strsplit (fileread (file), "\n");
  head = find (! cellfun ("isempty", strfind (L, ">>")), 1);
  if (isempty (head))
    problems{end+1} = "INDEX: no 'ctid >> ...' header line";
    head = 0;
  endif
  listed = {};
  for k = head+1:numel (L)
    l = L{k};
    if (isempty (strtrim (l)) || l(1) == "#")
      continue;
    elseif (any (l(1) == " \t"))
      if (isempty (cats))
        problems{end+1} = sprintf ("INDEX line %d: name before a category", k);
        continue;
      endif
      names = strsplit (strtrim (l));
      cats(end).names = [cats(end).names, names];
      listed = [listed, names];
    else
      cats(end+1) = struct ("title", strtrim (l), "names", {{}});
    endif
  endfor
  public = [funcs(:)', {classes([classes.ctor]).name}];
  for n = setdiff (public, listed)
    problems{end+1} = sprintf ("INDEX does not list %s", n{1});
  endfor
  for n = setdiff (listed, public)
    problems{end+1} = sprintf ("INDEX lists %s, which is not public", n{1});
  endfor
  [u, i] = unique (listed);
  for n = listed(setdiff (1:numel (listed), i))
    problems{end+1} = sprintf ("INDEX lists %s twice", n{1});
  endfor
endfunction

function write_page (file, lines)
  lines = cellfun (@(s) ifelse_cell (s), lines, "UniformOutput", false);
  txt = strjoin (lines, "\n");
  txt = regexprep (txt, '\n{3,}', "\n\n");
  [fid, msg] = fopen (file, "w");
  if (fid < 0)
    error ("make_reference:badInput", "make_reference: %s: %s", file, msg);
  endif
  fputs (fid, [strtrim(txt) "\n"]);
  fclose (fid);
endfunction

function s = ifelse_cell (s)
  if (iscell (s))
    s = strjoin (s, "\n");
  endif
endfunction

## Markdown of the help text of FILE (shown as NAME in messages), its
## first sentence, and the problems found.
function [md, summary, problems] = help_page (file, name, pages, anchors)
  problems = {};
  [txt, fmt] = get_help_text (file);
  summary = "";
  if (isempty (strtrim (txt)) || strcmp (fmt, "Not found")
      || strcmp (fmt, "Not documented"))
    problems{end+1} = sprintf ("%s: no help text", name);
    md = "(no help text)";
    return;
  endif
  src = fileread (file);
  if (isempty (regexp (txt, '@example\>', "once"))
      && isempty (regexp (src, '(^|\n)%!demo', "once")))
    problems{end+1} = sprintf ("%s: no example (@example or %%!demo)", name);
  endif
  if (strcmp (fmt, "texinfo"))
    if (nargin < 4)
      anchors = {};
    endif
    [md, summary] = texi2md (txt, pages, anchors);
  else
    md = sprintf ("```text\n%s\n```", strtrim (txt));
    summary = first_sentence (strtrim (txt));
  endif
  demos = demo_blocks (src);
  if (! isempty (demos))
    md = [md sprintf("\n\n**Demo** (`demo %s`):\n", name)];
    for k = 1:numel (demos)
      md = [md sprintf("\n```octave\n%s\n```\n", demos{k})];
    endfor
  endif
endfunction

## The code of the %!demo blocks of a file.
function demos = demo_blocks (src)
  demos = {};
  L = strsplit (src, "\n");
  k = 1;
  while (k <= numel (L))
    if (! isempty (regexp (L{k}, '^%!demo\s*$', "once")))
      code = {};
      k += 1;
      while (k <= numel (L) && strncmp (L{k}, "%!", 2)
             && isempty (regexp (L{k}, '^%![a-z]', "once")))
        code{end+1} = regexprep (L{k}, '^%! ?', "");
        k += 1;
      endwhile
      demos{end+1} = strtrim (strjoin (code, "\n"));
    else
      k += 1;
    endif
  endwhile
endfunction

function s = first_sentence (s)
  s = regexprep (s, '\s+', " ");
  e = regexp (s, '\.(\s|$)', "once");
  if (! isempty (e))
    s = s(1:e);
  endif
  if (numel (s) > 160)
    s = [s(1:157) "..."];
  endif
endfunction

## A light texinfo -> Markdown conversion of Octave help texts.
function [md, summary] = texi2md (txt, pages, anchors)
  L = strsplit (strrep (txt, "\r", ""), "\n");
  ## Join continued lines (a line ending in a single '@') and @seealso
  ## arguments spread over lines.
  J = {};
  k = 1;
  while (k <= numel (L))
    l = L{k};
    while (k < numel (L) && ! isempty (regexp (l, '(^|[^@])(@@)*@\s*$', "once")))
      k += 1;
      l = [regexprep(l, '\s*@\s*$', "") " " strtrim(L{k})];
    endwhile
    if (! isempty (strfind (l, "@seealso{")))
      while (k < numel (L) && isempty (strfind (l(strfind (l, "@seealso{")(1):end), "}")))
        k += 1;
        l = [l " " strtrim(L{k})];
      endwhile
    endif
    J{end+1} = l;
    k += 1;
  endwhile

  out = {};
  sigs = {};
  stack = {};          # open lists: "table:<fmt>", "itemize", "enumerate"
  inexample = false;
  skip = false;        # inside @tex / @iftex
  example = {};
  paragraph = {};      # plain text lines of the current paragraph
  for k = 1:numel (J)
    raw = J{k};
    l = strtrim (raw);
    if (skip)
      skip = isempty (regexp (l, '^@end\s+(tex|iftex|ifhtml|ifinfo)', "once"));
      continue;
    endif
    if (inexample)
      if (! isempty (regexp (l, '^@end\s+(example|smallexample|verbatim)', "once")))
        [out, paragraph] = flush (out, paragraph, stack);
        out = [out, fence(example, stack)];
        example = {};
        inexample = false;
      elseif (isempty (regexp (l, '^@(end )?group\s*$', "once")))
        example{end+1} = inline_md (regexprep (raw, '^ ', ""), true);
      endif
      continue;
    endif
    tok = regexp (l, '^@(\w+)\s*(.*)$', "tokens", "once");
    cmd = "";
    rest = "";
    if (! isempty (tok))
      cmd = tok{1};
      rest = tok{2};
    endif
    switch (cmd)
      case {"deftypefn", "deftypefnx"}
        sigs{end+1} = signature (rest);
        continue;
      case {"tex", "iftex", "ifhtml", "ifinfo"}
        skip = true;
        continue;
      case {"ifnottex", "group", "noindent", "sp", "c", "comment", "cindex"}
        continue;
      case {"example", "smallexample", "verbatim"}
        [out, paragraph] = flush (out, paragraph, stack);
        inexample = true;
        continue;
      case "table"
        [out, paragraph] = flush (out, paragraph, stack);
        stack{end+1} = ["table:" strrep(strtrim (rest), "@", "")];
        out{end+1} = "";
        continue;
      case {"itemize", "enumerate"}
        [out, paragraph] = flush (out, paragraph, stack);
        stack{end+1} = cmd;
        out{end+1} = "";
        continue;
      case {"item", "itemx"}
        [out, paragraph] = flush (out, paragraph, stack);
        if (isempty (stack))
          paragraph{end+1} = inline_md (rest, false);
          continue;
        endif
        ind = blanks (2 * (numel (stack) - 1));
        top = stack{end};
        if (strncmp (top, "table:", 6))
          f = top(7:end);
          label = inline_md (rest, any (strcmp (f, {"code", "samp", "var"})));
          if (any (strcmp (f, {"code", "samp"})))
            label = ["`" label "`"];
          elseif (strcmp (f, "var"))
            label = ["*" label "*"];
          elseif (strcmp (f, "strong"))
            label = ["**" label "**"];
          endif
          if (strcmp (cmd, "itemx") && ! isempty (out))
            out{end} = [regexprep(out{end}, ':$', "") ", " label ":"];
          else
            out{end+1} = [ind "- " label ":"];
          endif
        else
          mark = "- ";
          if (strcmp (top, "enumerate"))
            mark = "1. ";
          endif
          out{end+1} = [ind mark inline_md(rest, false)];
        endif
        continue;
      case "end"
        [out, paragraph] = flush (out, paragraph, stack);
        if (! isempty (regexp (rest, '^(table|itemize|enumerate)', "once"))
            && ! isempty (stack))
          stack(end) = [];
          out{end+1} = "";
        endif
        continue;
      case "seealso"
        [out, paragraph] = flush (out, paragraph, stack);
        arg = regexp (rest, '^\{(.*)\}', "tokens", "once");
        if (! isempty (arg))
          names = strtrim (strsplit (inline_md (arg{1}, true), ","));
          names = names(! cellfun ("isempty", names));
          out(end+1:end+2) = {"", ["**See also:** " strjoin(cellfun (@(n) link (n, pages, anchors), names, "UniformOutput", false), ", ")]};
        endif
        continue;
    endswitch
    if (isempty (l))
      [out, paragraph] = flush (out, paragraph, stack);
      out{end+1} = "";
    elseif (strncmp (l, "@strong{", 8) && isempty (stack))
      ## a bold lead-in starts a paragraph of its own
      [out, paragraph] = flush (out, paragraph, stack);
      out{end+1} = "";
      paragraph{end+1} = inline_md (l, false);
    else
      paragraph{end+1} = inline_md (l, false);
    endif
  endfor
  [out, paragraph] = flush (out, paragraph, stack);
  if (inexample)
    out = [out, fence(example, stack)];
  endif
  body = strjoin (out, "\n");
  summary = "";
  txtonly = regexprep (body, '```.*?```', "");
  txtonly = strtrim (regexprep (txtonly, '\n\s*\n.*', "", "once"));
  if (! isempty (txtonly))
    summary = first_sentence (txtonly);
  endif
  md = "";
  if (! isempty (sigs))
    md = ["```octave\n" strjoin(sigs, "\n") "\n```\n\n"];
  endif
  md = [md body];
endfunction

function [out, paragraph] = flush (out, paragraph, stack)
  if (! isempty (paragraph))
    ind = blanks (2 * numel (stack));
    if (! isempty (stack) && ! isempty (out) && ! isempty (out{end})
        && ! isempty (regexp (out{end}, '^\s*(-|1\.) ', "once")))
      ## continuation of a list item: the first line joins the item
      out{end} = [out{end} " " paragraph{1}];
      paragraph(1) = [];
    endif
    out = [out, strcat({ind}, paragraph)];
    paragraph = {};
  endif
endfunction

function c = fence (lines, stack)
  ind = blanks (2 * numel (stack));
  ## remove the common indentation
  nonempty = lines(! cellfun (@(s) isempty (strtrim (s)), lines));
  if (! isempty (nonempty))
    lead = min (cellfun (@(s) numel (s) - numel (regexprep (s, '^ +', "")), nonempty));
    lines = cellfun (@(s) s(min (lead, numel (s))+1:end), lines, "UniformOutput", false);
  endif
  c = [{"", [ind "```octave"]}, strcat({ind}, lines), {[ind "```"], ""}];
endfunction

function s = link (n, pages, anchors)
  base = regexprep (n, '^@\w+/', "");
  if (any (strcmp (base, anchors)))
    s = sprintf ("[%s](#%s)", base, lower (base));
  elseif (any (strcmp (base, pages)))
    s = sprintf ("[%s](%s.md)", base, base);
  elseif (any (strcmp (["class-" base], pages)))
    s = sprintf ("[%s](class-%s.md)", base, base);
  else
    s = ["`" n "`"];
  endif
endfunction

## "{category} {ret =} name (args)" -> "ret = name (args)".
function s = signature (rest)
  parts = {};
  r = strtrim (rest);
  for g = 1:2
    if (! isempty (r) && r(1) == "{")
      e = match_brace (r, 1);
      parts{end+1} = r(2:e-1);
      r = strtrim (r(e+1:end));
    endif
  endfor
  ret = "";
  if (numel (parts) >= 2)
    ret = strtrim (inline_md (parts{2}, true));
  endif
  s = strtrim ([ret " " inline_md(r, true)]);
endfunction

function e = match_brace (s, i)
  depth = 0;
  e = numel (s);
  k = i;
  while (k <= numel (s))
    c = s(k);
    if (c == "@" && k < numel (s))
      k += 2;
      continue;
    elseif (c == "{")
      depth += 1;
    elseif (c == "}")
      depth -= 1;
      if (depth == 0)
        e = k;
        return;
      endif
    endif
    k += 1;
  endwhile
endfunction

## Inline texinfo commands -> Markdown.  In code mode (inside a code span
## or block) commands keep their text only and nothing is escaped.
function out = inline_md (s, codemode)
  out = "";
  n = numel (s);
  k = 1;
  while (k <= n)
    c = s(k);
    if (c == "@" && k < n)
      d = s(k+1);
      if (any (d == "@{}"))
        out = [out esc(d, codemode)];
        k += 2;
        continue;
      elseif (isletter (d))
        j = k + 1;
        while (j <= n && isletter (s(j)))
          j += 1;
        endwhile
        cmd = s(k+1:j-1);
        arg = [];
        if (j <= n && s(j) == "{")
          e = match_brace (s, j);
          arg = s(j+1:e-1);
          k = e + 1;
        else
          k = j;
        endif
        out = [out render(cmd, arg, codemode)];
        continue;
      else
        k += 2;           # @* @. @: @- @/ and the like
        if (d == "*")
          out = [out " "];
        elseif (d != ":" && d != "-" && d != "/")
          out = [out d];
        endif
        continue;
      endif
    endif
    out = [out esc(c, codemode)];
    k += 1;
  endwhile
endfunction

function s = esc (c, codemode)
  if (! codemode && any (c == '*_`<\'))
    s = ["\\" c];
  else
    s = c;
  endif
endfunction

function s = render (cmd, arg, codemode)
  if (isempty (arg))
    arg = "";
  endif
  switch (cmd)
    case "var"
      s = inline_md (arg, true);
      if (! codemode)
        s = ["*" s "*"];
      endif
    case {"code", "qcode", "samp", "command", "env", "option", "kbd", "key", ...
          "file", "t", "verb"}
      s = inline_md (arg, true);
      if (! codemode)
        s = ["`" s "`"];
      endif
    case {"strong", "b"}
      s = inline_md (arg, codemode);
      if (! codemode)
        s = ["**" s "**"];
      endif
    case {"emph", "i", "dfn"}
      s = inline_md (arg, codemode);
      if (! codemode)
        s = ["*" s "*"];
      endif
    case "dots"
      s = "...";
    case "result"
      s = "=>";
    case "print"
      s = "-|";
    case "error"
      s = "error:";
    case "equiv"
      s = "==";
    case "expansion"
      s = "==>";
    case "minus"
      s = "-";
    case "bullet"
      s = "*";
    case {"tie", "w"}
      s = inline_md (arg, codemode);
      if (isempty (s))
        s = " ";
      endif
    case {"url", "uref"}
      p = strtrim (strsplit (arg, ","));
      if (codemode)
        s = p{1};
      elseif (numel (p) > 1)
        s = sprintf ("[%s](%s)", p{2}, p{1});
      else
        s = sprintf ("<%s>", p{1});
      endif
    case "footnote"
      s = [" (" inline_md(arg, codemode) ")"];
    case {"noindent", "refill", "*"}
      s = "";
    otherwise
      s = inline_md (arg, codemode);
  endswitch
endfunction

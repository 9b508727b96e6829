## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn  {} {@var{report} =} run_study (@var{name})
## @deftypefnx {} {@var{report} =} run_study (@var{name}, @var{arg1}, @dots{})
## Runs the development study @var{name} (a function or script in
## @file{devel/validation}, @file{devel/monte_carlo} or @file{bench}) on
## the current tree and writes a dated report,
## @file{devel/reports/YYYY-MM-DD-@var{name}.md}: when and on what it ran
## (UTC date, commit and whether the tree had local changes, Octave
## version, processor count and load, wall time), everything the study
## printed, the Markdown tables it wrote and the figures it left open
## (saved as PNG beside the report). A study that fails still gets its
## report, which then says so and with which error. The files the study
## writes go to @file{devel/reports/YYYY-MM-DD-@var{name}/}, its working
## folder. @var{arg1}, @dots{} are passed to a function study; a script
## study takes none.
##
## The shell wrapper @file{devel/run-study} calls it from the repository
## root:
## @example
## devel/run-study residtrace_suite 1
## devel/run-study rivc_mc
## @end example
## @end deftypefn

function report = run_study (name, varargin)
  if (nargin < 1 || ! ischar (name) || isempty (name))
    error ("run_study:badInput", "run_study: NAME must be a study's name");
  endif
  devel = fileparts (mfilename ("fullpath"));
  root = fileparts (devel);
  for d = {"octave", "demos", "bench", fullfile("devel", "validation"), ...
           fullfile("devel", "monte_carlo"), fullfile("tests", "octave")}
    addpath (fullfile (root, d{1}));
  endfor
  if (! any (exist (name) == [2 3]))
    error ("run_study:badInput", "run_study: no study named '%s'", name);
  endif
  tag = [strftime("%Y-%m-%d", gmtime (time ())) "-" name];
  if (! isempty (varargin))
    tag = [tag "-" regexprep(strjoin(cellfun (@disp_arg, varargin, ...
                                              "UniformOutput", false), "-"), ...
                             '[^A-Za-z0-9_.-]', "")];
  endif
  workdir = fullfile (devel, "reports", tag);
  if (! exist (workdir, "dir") && ! mkdir (workdir))
    error ("run_study:io", "run_study: cannot create %s", workdir);
  endif
  report = [workdir ".md"];
  output = fullfile (workdir, "output.txt");
  if (exist (output, "file"))
    delete (output);
  endif

  info.commit = shell_line (root, "git rev-parse --short HEAD");
  info.dirty = ! isempty (shell_line (root, "git status --porcelain --untracked-files=no"));
  info.load0 = load_average ();
  set (0, "defaultfigurevisible", "off");
  close all;
  here = pwd ();
  cd (workdir);
  diary (output);
  t0 = tic ();
  failure = "";
  unwind_protect
    try
      if (is_script (name))
        evalin ("base", name);
      else
        feval (name, varargin{:});
      endif
    catch err
      failure = sprintf ("%s (%s)", err.message, err.identifier);
      printf ("error: %s\n", failure);
    end_try_catch
  unwind_protect_cleanup
    diary off;
    cd (here);
  end_unwind_protect
  info.seconds = toc (t0);
  info.load1 = load_average ();
  figures = save_figures (workdir);
  write_report (report, name, varargin, info, failure, output, workdir, ...
                figures);
  printf ("report: %s\n", report);
endfunction

## An argument as text for the report's name: a cell's elements joined
## (mat2str takes numbers, logicals and characters only).
function s = disp_arg (a)
  if (ischar (a))
    s = a;
  elseif (iscell (a))
    s = strjoin (cellfun (@disp_arg, a, "UniformOutput", false), "_");
  elseif (isnumeric (a) || islogical (a))
    s = mat2str (a);
  else
    s = class (a);
  endif
endfunction

function tf = is_script (name)
  tf = false;
  try
    nargin (name);
  catch
    tf = true;
  end_try_catch
endfunction

function s = shell_line (root, cmd)
  [st, s] = system (sprintf ("cd '%s' && %s 2>/dev/null", root, cmd));
  if (st != 0)
    s = "";
  endif
  s = strtrim (s);
endfunction

function s = load_average ()
  s = "";
  fid = fopen ("/proc/loadavg", "r");
  if (fid >= 0)
    s = strtrim (fgetl (fid));
    fclose (fid);
    s = strjoin (strsplit (s)(1:3), " ");
  endif
endfunction

function files = save_figures (workdir)
  files = {};
  h = sort (get (0, "children"));
  for k = 1:numel (h)
    f = sprintf ("figure_%d.png", k);
    try
      print (h(k), fullfile (workdir, f), "-dpng");
      files{end+1} = f;
    catch
    end_try_catch
  endfor
  close all;
endfunction

function write_report (report, name, args, info, failure, output, workdir, ...
                       figures)
  fid = fopen (report, "w");
  if (fid < 0)
    error ("run_study:io", "run_study: cannot write %s", report);
  endif
  closer = onCleanup (@() fclose (fid));
  [~, dir] = fileparts (workdir);
  call = name;
  if (! isempty (args))
    call = sprintf ("%s (%s)", name, strjoin (cellfun (@quoted_arg, args, ...
                                                      "UniformOutput", false), ", "));
  endif
  fprintf (fid, "# %s\n\n", call);
  fprintf (fid, "| | |\n|---|---|\n");
  fprintf (fid, "| date (UTC) | %s |\n", ...
           strftime ("%Y-%m-%d %H:%M", gmtime (time ())));
  commit = info.commit;
  if (info.dirty)
    commit = [commit " (with local changes)"];
  endif
  fprintf (fid, "| commit | %s |\n", commit);
  fprintf (fid, "| Octave | %s |\n", OCTAVE_VERSION);
  fprintf (fid, "| processors | %d |\n", nproc ());
  fprintf (fid, "| load average at start / end | %s / %s |\n", ...
           info.load0, info.load1);
  fprintf (fid, "| wall time | %.1f s |\n", info.seconds);
  if (isempty (failure))
    fprintf (fid, "| result | completed |\n\n");
  else
    fprintf (fid, "| result | failed: %s |\n\n", strrep (failure, "|", "/"));
  endif
  fprintf (fid, "## Output\n\n```\n%s\n```\n", strtrim (fileread (output)));
  written = dir_files (workdir);
  for k = 1:numel (written)
    f = written{k};
    if (strcmp (f, "output.txt") || any (strcmp (f, figures)))
      continue;
    endif
    fprintf (fid, "\n## %s\n\n", f);
    [~, ~, ext] = fileparts (f);
    if (strcmp (ext, ".md"))
      fprintf (fid, "%s\n", strtrim (fileread (fullfile (workdir, f))));
    else
      fprintf (fid, "Written to `%s/%s`.\n", dir, f);
    endif
  endfor
  for k = 1:numel (figures)
    fprintf (fid, "\n![figure %d](%s/%s)\n", k, dir, figures{k});
  endfor
endfunction

## An argument as the call in the report's title writes it.
function s = quoted_arg (a)
  if (ischar (a))
    s = ["\"" a "\""];
  elseif (iscell (a))
    s = ["{" strjoin(cellfun (@quoted_arg, a, "UniformOutput", false), ", ") "}"];
  elseif (isnumeric (a) || islogical (a))
    s = mat2str (a);
  else
    s = ["<" class(a) ">"];
  endif
endfunction

function names = dir_files (d)
  names = {};
  stack = {""};
  while (! isempty (stack))
    rel = stack{end};
    stack(end) = [];
    L = dir (fullfile (d, rel));
    for k = 1:numel (L)
      if (any (strcmp (L(k).name, {".", ".."})))
        continue;
      endif
      r = fullfile (rel, L(k).name);
      if (L(k).isdir)
        stack{end+1} = r;
      else
        names{end+1} = r;
      endif
    endfor
  endwhile
  names = sort (names);
endfunction

%!error <NAME must be> run_study ()
%!error <no study named> run_study ("no_such_study_here")
%!test
%! ## A tiny script study in a temporary folder: the report holds its
%! ## output, the table it wrote and the call's metadata; a failing
%! ## function study still gets a report that names its error.
%! d = tempname (); mkdir (d);
%! fid = fopen (fullfile (d, "tiny_study_for_test.m"), "w");
%! fprintf (fid, "disp ('printed line 42');\n");
%! fprintf (fid, "f = fopen ('table.md', 'w'); fprintf (f, '| a |\\n|---|\\n| 7 |\\n'); fclose (f);\n");
%! fclose (fid);
%! fid = fopen (fullfile (d, "failing_study_for_test.m"), "w");
%! fprintf (fid, "function failing_study_for_test (n)\n");
%! fprintf (fid, "  error ('study:odd', 'odd count %%d', n);\nend\n");
%! fclose (fid);
%! addpath (d);
%! r1 = r2 = r3 = "";
%! unwind_protect
%!   r1 = run_study ("tiny_study_for_test");
%!   s = fileread (r1);
%!   assert (! isempty (strfind (s, "printed line 42")));
%!   assert (! isempty (strfind (s, "## table.md")));
%!   assert (! isempty (strfind (s, "| 7 |")));
%!   assert (! isempty (strfind (s, "| result | completed |")));
%!   assert (! isempty (regexp (s, '\| wall time \| [0-9.]+ s \|', "once")));
%!   r2 = run_study ("failing_study_for_test", 3);
%!   s = fileread (r2);
%!   assert (! isempty (strfind (s, "# failing_study_for_test (3)")));
%!   assert (! isempty (strfind (s, "failed: odd count 3 (study:odd)")));
%!   ## a cell argument (a list of cases) is written into the name and title
%!   r3 = run_study ("failing_study_for_test", {"tanks", 2});
%!   s = fileread (r3);
%!   assert (! isempty (strfind (s, '# failing_study_for_test ({"tanks", 2})')));
%!   assert (! isempty (strfind (r3, "tanks_2")));
%! unwind_protect_cleanup
%!   evalin ("base", "clear f");
%!   rmpath (d);
%!   confirm_recursive_rmdir (false, "local");
%!   rmdir (d, "s");
%!   for r = {r1, r2, r3}
%!     if (exist (r{1}, "file")) delete (r{1}); rmdir (r{1}(1:end-3), "s"); endif
%!   endfor
%! end_unwind_protect

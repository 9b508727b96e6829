## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {} test_fuzz_public ()
## Seeded random malformed calls to every public function, class
## constructor and method (found by listing @file{octave/*.m} and
## @file{octave/@@*/*.m}, so that new functions are covered without editing
## this file) and every compiled gateway (@file{octave/private/*.mex}).
##
## The calls run in child @code{octave-cli} processes (see
## @file{fuzz_public_child.m}) under @code{timeout}, in batches, so that a
## crash or a hang ends only the child: the parent then records the call
## that was running and goes on with the next.  The test fails on
## @itemize
## @item a crash (the child died) or a hang (the batch hit its time limit);
## @item an error without an identifier @code{<name>:<reason>}, where
## <name> is the function called (for a method also its class or the
## class of the object it was called on, a subclass that inherits it; for a
## gateway any non-Octave name, since the caller's name is passed in);
## @item an accepted call with non-finite inputs (NaN or Inf anywhere in
## its arguments) that returns non-finite numbers silently.  NaN in a
## record is a missing sample that the estimators bridge (their outputs
## are then finite); the @code{iddata} class, a container, is exempt, as
## it holds what it is given, and so is @code{residtrace}, whose result
## marks the figures that do not apply with NaN (a tracked RMSE without
## drift, the score of an untested candidate) whatever its input, and so
## is @code{idproc}, whose parameters not given are NaN by design (to be
## estimated), and @code{idtraced} (the model @code{residtrace} returns),
## which holds NaN for a standard deviation the fit does not give and
## -Inf for the missing side of a one-sided saturation.  A model's @code{UserData} is the user's own and is not
## looked at.
## @end itemize
## An error that a public function re-raised under its name from an inner
## failure (@code{contsid_guard}; a reason that is not one of the
## toolbox's own, such as @code{indexOutOfBounds} or @code{failed}) counts
## as identified, but the first ones are listed, as hints of a missing
## check.
## The children run in a temporary working directory, removed at the end;
## a call that leaves a new file in the test or source folders is a
## failure.
## The number of calls is @env{CTID_FUZZ_CALLS} (default 10000) and the
## seed @env{CTID_FUZZ_SEED} (default 12).  @env{CTID_FUZZ_ONLY}, a
## comma-separated list of names (functions, classes or gateways), limits
## the targets to those, for a developer checking new functions.  A
## summary (calls, accepted, identified errors, failures by kind, slowest
## calls) is printed.
##
## Completeness: the targets are found by listing the folders (the
## methods of @@double, the pre-LTI numeric forms, get calls with
## built-in arguments only, once although other built-in classes' folders
## link to them); every gateway of @file{mex/CMakeLists.txt}'s
## @code{CTID_GATEWAYS} must be built, and every public function must
## have well-formed calls in @file{fuzz_public_templates.m} (which the
## child mutates, 70 % of the calls to a function; methods and
## constructors may have some there too, 50 % of their calls); the test
## fails otherwise, so that the lists stay complete as the API grows.
## @end deftypefn

function test_fuzz_public ()
  root = ctid_test_root ();
  root = canonicalize_file_name (root);
  ncalls = env_number ("CTID_FUZZ_CALLS", 10000);
  seed = env_number ("CTID_FUZZ_SEED", 12);
  tmp = tempname ();
  mkdir (tmp);
  cleanup = onCleanup (@() remove_dir (tmp));
  [targets, gwdir] = discover (root, tmp);
  ## Every public function has well-formed calls in fuzz_public_templates,
  ## and every entry there is a public function.
  addpath (fullfile (root, "octave"));
  own = fieldnames (fuzz_public_templates ());
  funcs = {targets(strcmp ({targets.kind}, "function")).name};
  if (! isempty (setdiff (funcs, own)))
    error ("test_fuzz_public: no template in fuzz_public_templates for %s",
           strjoin (setdiff (funcs, own), ", "));
  endif
  ## methods and constructors may have calls there too, as <class>_<name>
  meth = targets(! strcmp ({targets.kind}, "function")
                 & ! strcmp ({targets.kind}, "gateway"));
  keys = strcat ({meth.cls}, "_", {meth.name});
  if (! isempty (setdiff (own, [funcs, keys])))
    error ("test_fuzz_public: fuzz_public_templates names no function %s",
           strjoin (setdiff (own, funcs), ", "));
  endif
  only = getenv ("CTID_FUZZ_ONLY");
  if (! isempty (only))
    names = strtrim (strsplit (only, ","));
    keep = ismember ({targets.name}, names) | ismember ({targets.cls}, names);
    targets = targets(keep);
    if (isempty (targets))
      error ("test_fuzz_public: CTID_FUZZ_ONLY matches no target: %s", only);
    endif
  endif
  printf ("test_fuzz_public: %d targets, %d calls, seed %d\n",
          numel (targets), ncalls, seed);

  ## The children run in a working directory of their own inside tmp
  ## (removed at the end): a call that writes a file under a name it was
  ## given (residtrace's 'table' option) writes it there, never into the
  ## source tree (e.g. a file tests/octave/InterSample). The folders the
  ## children would otherwise run in and the sources' are listed before
  ## and after, and a new file there is a failure.
  here = fileparts (mfilename ("fullpath"));
  work = fullfile (tmp, "work");
  mkdir (work);
  watched = {here, fullfile(root, "octave")};
  before = cellfun (@(d) {dir(d).name}, watched, "UniformOutput", false);

  nbatch = 8;
  per = ceil (ncalls / nbatch);
  batch_timeout = 600;
  log = fullfile (tmp, "calls.log");
  res = struct ("k", {}, "status", {}, "id", {}, "nonfinite", {},
                "sec", {}, "name", {}, "objcls", {}, "msg", {});
  failures = {};
  t0 = time ();
  for b = 1:nbatch
    first = (b - 1) * per + 1;
    last = min (ncalls, b * per);
    while (first <= last)
      specfile = fullfile (tmp, "spec.mat");
      logfile = log;
      save ("-binary", specfile, "root", "logfile", "targets", "first",
            "last", "seed", "gwdir");
      if (exist (log, "file"))
        unlink (log);
      endif
      cmd = sprintf (["cd %s && timeout -s KILL %d octave-cli -q ", ...
                      "--no-gui --no-window-system --eval ", ...
                      "\"addpath ('%s'); fuzz_public_child ('%s')\" ", ...
                      "> %s 2>&1"],
                     work, batch_timeout, here, specfile,
                     fullfile (tmp, "child.out"));
      rc = system (cmd);
      [r, started] = read_log (log);
      res = [res, r];
      if (rc == 0 && (isempty (r) || r(end).k == last))
        break;
      endif
      ## The child died (crash) or was killed (hang) during call `started`.
      kind = "crash";
      if (rc == 137 || rc == 124)
        kind = "hang";
      endif
      if (isempty (started) && isempty (r))
        error ("test_fuzz_public: child failed before any call (rc %d): %s",
               rc, fileread (fullfile (tmp, "child.out")));
      elseif (isempty (started))
        started = r(end).k + 1;          # died between calls
      endif
      i = mod (started - 1, numel (targets)) + 1;
      failures{end+1} = sprintf ("%s in call %d (%s), rc %d", kind, started,
                                 targets(i).name, rc);
      first = started + 1;
    endwhile
  endfor
  elapsed = time () - t0;
  for w = 1:numel (watched)
    added = setdiff ({dir(watched{w}).name}, before{w});
    if (! isempty (added))
      failures{end+1} = sprintf ("the calls wrote %s into %s",
                                 strjoin (added, ", "), watched{w});
    endif
  endfor

  ## Check the outcome of every call.
  nok = 0; nid = 0;
  ## The reasons the toolbox's own checks give; any other reason is that
  ## of an inner failure (Octave's, the control package's) that the
  ## public function re-raised under its name (contsid_guard): identified,
  ## but listed below, as a hint of a check missing.
  own_reasons = {"badInput", "badOption", "dimensionMismatch", ...
                 "notSupported", "notConverged", "numericalFailure", ...
                 "overParameterised", "unstableStart", "unstable", ...
                 "integratorDetected"};
  inner = {};
  for j = 1:numel (res)
    r = res(j);
    i = mod (r.k - 1, numel (targets)) + 1;
    tgt = targets(i);
    if (strcmp (r.status, "ok"))
      nok += 1;
      if (r.nonfinite && ! strcmp (tgt.cls, "iddata")
          && ! strcmp (tgt.name, "residtrace")
          && ! any (strcmp ("idtraced", {tgt.cls, r.objcls}))
          && ! any (strcmp ("idproc", {tgt.cls, r.objcls})))
        failures{end+1} = sprintf (["call %d (%s): non-finite inputs ", ...
                                    "gave non-finite outputs"], r.k,
                                   tgt.name);
      endif
    elseif (identified (r.id, tgt, r.objcls))
      nid += 1;
      if (! any (strcmp (regexprep (r.id, '^.*:', ""), own_reasons)))
        inner{end+1} = sprintf ("call %d (%s): %s: %s", r.k, tgt.name, r.id,
                                r.msg);
      endif
    else
      failures{end+1} = sprintf ("call %d (%s): error id '%s': %s", r.k,
                                 tgt.name, r.id, r.msg);
    endif
  endfor
  [~, slow] = sort ([res.sec], "descend");
  printf ("test_fuzz_public: %d calls in %.0f s: %d accepted, %d errors ",
          numel (res), elapsed, nok, nid);
  printf ("with identifier, %d failures\n", numel (failures));
  printf ("  %d identified errors re-raised from an inner failure\n",
          numel (inner));
  for j = 1:min (10, numel (inner))
    printf ("    %s\n", inner{j});
  endfor
  for j = slow(1:min(5, end))
    printf ("  slowest: call %d (%s) %.2f s\n", res(j).k, res(j).name,
            res(j).sec);
  endfor
  names = unique ({res.name});
  for j = 1:numel (names)
    sel = strcmp ({res.name}, names{j});
    fails = failures(! cellfun ("isempty",
                                strfind (failures, ["(" names{j} ")"])));
    printf ("  %-22s %5d calls, %4d accepted, %4d failures\n", names{j},
            nnz (sel), nnz (sel & strcmp ({res.status}, "ok")),
            numel (fails));
    for i = 1:min (2, numel (fails))
      printf ("    FAIL %s\n", fails{i});
    endfor
  endfor
  for j = 1:numel (failures)
    if (! isempty (regexp (failures{j}, "^(crash|hang)", "once")))
      printf ("  FAIL %s\n", failures{j});
    endif
  endfor
  if (! isempty (failures))
    error ("test_fuzz_public: %d failures (first: %s)", numel (failures),
           failures{1});
  endif
  if (numel (res) < ncalls)
    error ("test_fuzz_public: only %d of %d calls ran", numel (res), ncalls);
  endif
endfunction

## Every public function, class constructor and method, and every gateway
## (copied to a folder of their own so that the child can call them).
function [targets, gwdir] = discover (root, tmp)
  targets = struct ("name", {}, "kind", {}, "cls", {});
  f = dir (fullfile (root, "octave", "*.m"));
  for i = 1:numel (f)
    targets(end+1) = struct ("name", f(i).name(1:end-2), "kind",
                             "function", "cls", "");
  endfor
  c = dir (fullfile (root, "octave", "@*"));
  ## @double first: its methods are linked into other built-in classes'
  ## folders, and count under it
  [~, k] = sort (! strcmp ({c.name}, "@double"));
  c = c(k);
  seen = {};
  for i = 1:numel (c)
    cls = c(i).name(2:end);
    m = dir (fullfile (root, "octave", c(i).name, "*.m"));
    for j = 1:numel (m)
      ## a method file linked into several class folders (@double's
      ## step, bode, pzmap) is one target
      file = canonicalize_file_name (fullfile (m(j).folder, m(j).name));
      if (any (strcmp (file, seen)))
        continue;
      endif
      seen{end+1} = file;
      name = m(j).name(1:end-2);
      kind = "method";
      if (strcmp (name, cls))
        kind = "constructor";
      endif
      targets(end+1) = struct ("name", name, "kind", kind, "cls", cls);
    endfor
  endfor
  g = dir (fullfile (root, "octave", "private", "*.mex"));
  gwdir = "";
  if (! isempty (g))
    gwdir = fullfile (tmp, "gateways");
    mkdir (gwdir);
  endif
  for i = 1:numel (g)
    copyfile (fullfile (root, "octave", "private", g(i).name), gwdir);
    targets(end+1) = struct ("name", g(i).name(1:end-4), "kind", "gateway",
                             "cls", "");
  endfor
  ## Every gateway of mex/CMakeLists.txt's CTID_GATEWAYS must be built, or
  ## it would escape the test.
  txt = fileread (fullfile (root, "mex", "CMakeLists.txt"));
  tok = regexp (txt, 'set\(CTID_GATEWAYS\s+([^)]*)\)', "tokens", "once");
  if (isempty (tok))
    error ("test_fuzz_public: no set(CTID_GATEWAYS ...) in %s",
           "mex/CMakeLists.txt");
  endif
  unbuilt = setdiff (regexp (tok{1}, '\w+', "match"),
                     {targets(strcmp ({targets.kind}, "gateway")).name});
  if (! isempty (unbuilt))
    error ("test_fuzz_public: gateway(s) of CTID_GATEWAYS not built: %s",
           strjoin (unbuilt, ", "));
  endif
endfunction

## An identifier <name>:<reason> naming the function called (or the class
## of a method); a gateway receives the caller's name, so any name but
## Octave's own counts.
function tf = identified (id, tgt, objcls)
  tok = regexp (id, '^([A-Za-z]\w*):([A-Za-z]\w*)$', "tokens", "once");
  if (isempty (tok))
    tf = false;
  elseif (strcmp (tgt.kind, "gateway"))
    tf = ! strcmp (tok{1}, "Octave");
  else
    tf = any (strcmp (tok{1}, {tgt.name, tgt.cls, objcls}));
  endif
endfunction

function [r, started] = read_log (log)
  r = struct ("k", {}, "status", {}, "id", {}, "nonfinite", {}, "sec", {},
              "name", {}, "objcls", {}, "msg", {});
  started = [];
  msgs = {};
  if (! exist (log, "file"))
    return;
  endif
  lines = strsplit (fileread (log), "\n");
  for i = 1:numel (lines)
    w = strsplit (strtrim (lines{i}), " ");
    if (numel (w) >= 1 && strcmp (w{1}, "S"))
      started = str2double (w{2});
    elseif (numel (w) >= 3 && strcmp (w{1}, "M"))
      msg = strjoin (w(3:end), " ");
      msgs{end+1} = msg(1:min(end, 100));
    elseif (numel (w) >= 7 && strcmp (w{1}, "R"))
      r(end+1) = struct ("k", str2double (w{2}), "status", w{3}, "id", w{4},
                         "nonfinite", str2double (w{5}), "sec",
                         str2double (w{6}), "name", w{7}, "objcls", "-",
                         "msg", "");
      if (numel (w) >= 8)
        r(end).objcls = w{8};
      endif
      if (! isempty (msgs))
        r(end).msg = msgs{end};
        msgs = {};
      endif
      started = [];
    endif
  endfor
endfunction

function remove_dir (d)
  confirm_recursive_rmdir (false, "local");
  rmdir (d, "s");
endfunction

function v = env_number (name, def)
  v = str2double (getenv (name));
  if (isnan (v))
    v = def;
  endif
endfunction

## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {} fuzz_public_child (@var{specfile})
## The child process of @file{test_fuzz_public.m}: makes the seeded random
## malformed calls listed in @var{specfile} (a MAT file with the fields
## root, logfile, targets (struct array: name, kind, cls), first, last and
## seed) and logs each call to @var{logfile} before (@code{S k}) and after
## it (@code{R k status identifier nonfinite seconds name class}, the
## class being that of the object a method was called on), flushing every line
## so that the parent can tell which call crashed or hung.
## @end deftypefn

function fuzz_public_child (specfile)
  spec = load (specfile);
  addpath (fullfile (spec.root, "octave"));
  if (! isempty (spec.gwdir))
    addpath (spec.gwdir);
  endif
  warning ("off", "all");
  more off;
  graphics_toolkit ("gnuplot");          # never opens a window
  set (0, "defaultfigurevisible", "off");
  fid = fopen (spec.logfile, "a");
  for k = spec.first:spec.last
    [tgt, kidx] = call_target (spec, k);
    rand ("state", spec.seed * 1e6 + k);
    randn ("state", spec.seed * 1e6 + k);
    [args, nout] = make_call (tgt);
    objcls = "-";
    if (strcmp (tgt.kind, "method"))
      objcls = class (args{1});        # a subclass inheriting the method
    endif
    fprintf (fid, "S %d\n", k);
    fflush (fid);
    t_run = tic ();
    status = "ok"; id = "-"; nonfinite = 0;
    try
      outs = cell (1, nout);
      if (nout == 0)
        feval (tgt.name, args{:});
      else
        [outs{:}] = feval (tgt.name, args{:});
      endif
      nonfinite = has_nonfinite (args) && has_nonfinite (outs);
    catch err
      status = "err";
      id = err.identifier;
      if (isempty (id))
        id = "-";
      endif
      fprintf (fid, "M %d %s\n", k, strrep (err.message, "\n", " "));
    end_try_catch
    close all;
    fprintf (fid, "R %d %s %s %d %.3f %s %s\n", k, status, id, nonfinite,
             toc (t_run), tgt.name, objcls);
    fflush (fid);
  endfor
  fclose (fid);
endfunction

## Call k of the spec goes to target mod (k - 1, ntargets) + 1, so that
## every batch spreads over every target.
function [tgt, i] = call_target (spec, k)
  i = mod (k - 1, numel (spec.targets)) + 1;
  tgt = spec.targets(i);
endfunction

## A call: a plausible template for the target's kind, then zero to three
## mutations (an argument replaced by a malformed value, removed,
## inserted, or a name-value pair appended), and a random number of
## outputs (up to two more than any public function returns).
function [args, nout] = make_call (tgt)
  persistent pool templates names own
  if (isempty (pool))
    [pool, templates, names] = value_pool ();
    own = fuzz_public_templates ();
  endif
  ## methods of the built-in classes: the pre-LTI step/bode/pzmap forms
  numeric = any (strcmp (tgt.cls, {"double", "single", "int8", "int16", ...
                                   "int32", "int64", "uint8", "uint16", ...
                                   "uint32", "uint64", "logical", "char", ...
                                   "cell", "struct", "function_handle"}));
  ## A method's or constructor's own calls in fuzz_public_templates are
  ## under <class>_<name> (half of its calls start from them).
  key = [tgt.cls "_" tgt.name];
  if (! strcmp (tgt.kind, "gateway") && isfield (own, key) && rand () < 0.5)
    args = pick (own.(key));
  elseif (strcmp (tgt.kind, "method"))
    if (numeric)
      ## A method of a built-in class (the pre-LTI step/bode/pzmap
      ## forms): its calls are numeric (see mpool below).
      args = pick (numeric_templates ());
      args = args(1:randi (numel (args)));
      obj = [];
    else
      obj = object_of (tgt.cls);
    endif
    if (! numeric)
      tpl = pick (templates);
      args = [{obj}, tpl(2:end)];
      args = args(1:randi (numel (args)));
    endif
  elseif (strcmp (tgt.kind, "gateway"))
    args = [{tgt.name(1:end-4)}, pick(templates)];
  else
    ## The function's own well-formed calls (fuzz_public_templates) or,
    ## less often, a generic one.
    if (isfield (own, tgt.name) && rand () < 0.7)
      args = pick (own.(tgt.name));
    else
      args = pick (templates);
      endif
  endif
  mpool = pool;
  if (numeric)
    ## No object: a call with an object goes to the control package (or
    ## the object's class), not to these methods.  The built-in classes
    ## other than double link to the same files (a call whose arguments
    ## are all built-in goes to the highest of their classes).
    mpool = pool(! cellfun ("isobject", pool));
  endif
  nmut = randi ([0 3]);                  # 0: a well-formed call
  for m = 1:nmut
    r = rand ();
    first = 1 + strcmp (tgt.kind, "method");   # keep the object (or number)
    if (r < 0.5 && numel (args) >= first)
      j = randi ([first, max(first, numel(args))]);
      args{j} = pick (mpool);
    elseif (r < 0.65 && numel (args) > first)
      args(randi ([first, numel(args)])) = [];
    elseif (r < 0.8)
      j = randi ([first, numel(args) + 1]);
      args = [args(1:j-1), {pick(mpool)}, args(j:end)];
    else
      args(end+1:end+2) = {pick(names), pick(mpool)};
    endif
  endfor
  w = rand ();
  if (w < 0.15)
    nout = 0;
  elseif (w < 0.6)
    nout = 1;
  else
    nout = randi ([2 7]);
  endif
endfunction

## Valid calls of the pre-LTI numeric forms (num, den[, w or t]) and
## (a, b, c, d[, iu[, w or t]]).
function tpl = numeric_templates ()
  tpl = {{1, [1 3 2]}, {[1 2], [1 3 2], logspace(-1, 1, 5)}, ...
         {-1, 1, 1, 0}, {-1, 1, 1, 0, 1}, {-eye(2), [1; 0], [0 1], 0, 1, ...
         (0:0.1:1)'}, {2, [1 1], (0:0.5:3)}};
endfunction

function v = pick (c)
  v = c{randi (numel (c))};
endfunction

function obj = object_of (cls)
  [y, u, Ts] = small_record ();
  switch (cls)
    case "iddata"
      obj = iddata (y, u, Ts);
    case "idctm"
      obj = idctm (2, [1 2]);
    case {"idmodel", "idtf"}
      ## idmodel is the abstract parent: its methods run on a subclass.
      obj = idtf (2, [1 3 2]);
    case "idpoly"
      obj = idpoly (1, 2, 1, 1, [1 3 2], "Ts", 0);
    case "idss"
      obj = idss (-1, 1, 1, 0);
    case "idproc"
      obj = idproc ("P1D", "Kp", 2, "Tp1", 0.5, "Td", 0.1);
    case "idfrd"
      obj = idfrd (1 ./ (1i * (1:5)' + 1), (1:5)', "Ts", 0);
    otherwise
      obj = feval (cls);
  endswitch
endfunction

function [y, u, Ts] = small_record ()
  Ts = 0.1;
  n = 40;
  u = sign (sin ((1:n)' * 0.7 + 0.3));
  y = filter (0.3, [1 -0.7], u) + 0.01 * sin ((1:n)' * 2.1);
endfunction

function [pool, templates, names] = value_pool ()
  [y, u, Ts] = small_record ();
  n = numel (y);
  data = iddata (y, u, Ts);
  yn = y; yn(5) = NaN;
  yi = y; yi(7) = Inf;
  un = u; un(9:11) = NaN;
  M = idctm (2, [1 2]);
  thm = repmat ([2 3], n, 1);
  R.steps = struct ("label", {"a", 1}, "params", {[], struct("x", 1)});
  pool = {NaN, Inf, -Inf, [], {}, "", "abc", int8(3), uint16([1 2]), ...
          sparse(y), sparse(1), true, false, 1e9, 1e15, -1, 0, 2.5, ...
          1+2i, y + 1i, yn, yi, un, [y y], randn(3, 1), ...
          randn(n, 1, 2), @sin, struct(), struct("a", 1), cell(2), ...
          single(y), realmax, -realmax, [2 1 0], [1e9 1 0], [2 1 1e9], ...
          [30 1 0], [2 1 0 0 0], [2 1 1], [1 1], [0 1 0], [2 -1 0], ...
          "zoh", "foh", data, iddata(yn, u, Ts), iddata(y, [u un], Ts), ...
          M, thm, thm(:, 1), y, u, Ts, (0:n-1)' * Ts, ...
          flipud((0:n-1)' * Ts), NaN(n, 1), zeros(n, 1), ones(n, 1), ...
          R, struct("steps", 1), 3, 1e-300, [1 2; 3 4], eye(3), ...
          "lambda_svf", "adm", "kf", "ff", 0.98, {1, "a"}};
  templates = {{data, [2 1 0], "lambda_svf", 3}, ...
               {y, u, Ts, [2 1 0], "lambda_svf", 3}, ...
               {data, [1 2 0], "lambda_svf", 3}, ...
               {data, [1 1 0]}, ...
               {M, data}, {M, u, Ts}, {thm, [1 1 0], data}, ...
               {y, u, Ts}, {data}, {}, {R}, {2, [1 2]}, ...
               {data, "rsrivc"}, {y, u, Ts, [1 1 0], 3}};
  names = {"lambda_svf", "adm", "adg", "th0", "P0", "svf", "tsiv", ...
           "dtupdate", "stability", "mtheta", "prefilter", "A", ...
           "controller", "r1", "r2", "scaling", "antiwindup", ...
           "precision", "Missing", "potter", "Gamma", "ic", "tsls", ...
           "InitMethod", "Tol", "MaxIter", "nk", "Ts", "InterSample", ...
           "order", "criteria", "blocklength", "SNR", "x0", "lambda"};
endfunction

## True when a numeric or logical value anywhere in x (cells, structs,
## objects through struct ()) is NaN or Inf.
function tf = has_nonfinite (x)
  tf = false;
  if (isnumeric (x))
    tf = ! all (isfinite (x(:)));
  elseif (iscell (x))
    for i = 1:numel (x)
      if (has_nonfinite (x{i}))
        tf = true;
        return;
      endif
    endfor
  elseif (isstruct (x) || isobject (x))
    if (isobject (x))
      try
        x = struct (x);
      catch
        return;
      end_try_catch
    endif
    ## UserData is the user's own payload, stored as given (as an iddata
    ## holds its samples): not a result of the call.
    if (isfield (x, "UserData"))
      x = rmfield (x, "UserData");
    endif
    c = struct2cell (x(:));
    tf = has_nonfinite (c(:).');
  endif
endfunction

## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {} test_options_declared_once ()
## The options of the recursive estimators are declared once, in the core
## (@file{core/include/ctid/recursive/recursive_options.hpp}), and the
## gateways return that table (@code{riv_mex (fname, "options")},
## @code{rlssvf_mex ("rlssvf", "options")}); those of the output-error
## estimators likewise
## (@file{core/include/ctid/offline/output_error_options.hpp},
## @code{pem_mex ("oe", "options")}), of the frequency-domain estimators
## (@file{core/include/ctid/offline/freq_srivc_options.hpp},
## @code{freq_srivc_mex ("tffsrivc", "options")}), and those of the
## refined-IV estimators
## (@file{core/include/ctid/offline/refined_iv_options.hpp},
## @code{refined_iv_mex ("srivc", "options")},
## @code{rivc_mex ("rivc", "options")}), and CONTSID's tfsrivc defaults
## of tfsrivc, tfsrivc_init and tfrivc
## (@file{core/include/ctid/offline/tfsrivc_options.hpp},
## @code{refined_iv_mex ("tfsrivc", "tf_options", "options")}). Checked
## here:
## @itemize
## @item every option a user sets is documented in the help text of its
## front-ends, and where the help states a default, it is the table's;
## @item a front-end leaves an option it is not given to the core: giving
## it the table's default explicitly changes nothing, option by option;
## @item an option the table does not declare is refused by the gateway.
## @end itemize
## @end deftypefn

function test_options_declared_once ()
  root = ctid_test_root ();
  private_dir = fullfile (root, "octave", "private");
  addpath (private_dir);
  cleanup = onCleanup (@() rmpath (private_dir));

  ## Options the front-ends set from something else than an option of the
  ## same name: the orders (nn), the data's InterSample, the routine
  ## (method), the gaps of the bridged record, the polynomial pairs.
  derived = {"na", "nb", "nk", "intersample", "method", "gap_interval", ...
             "gap_settle", "mtheta_den", "controller_den", "kernels"};
  user_name = struct ("mtheta_num", "mtheta", "controller_num", "controller",
                      "form", "potter");

  families = cell (2, 3);
  families(1, :) = {"riv_mex", "rsrivc", ...
                    {"rlssvf", "rivsvf", "rsrivc", "clrivsvf", "clrsrivc"}};
  families(2, :) = {"rlssvf_mex", "rlssvf", {"rlssvf"}};
  compared = 0;                          # defaults stated by a help text
  for f = 1:rows (families)
    [gw, fname, fronts] = families{f, :};
    T = feval (gw, fname, "options");
    assert (isstruct (T) && numel (T) > 10);
    help_text = "";
    for k = 1:numel (fronts)
      help_text = [help_text, "\n", get_help_text(fronts{k})];
    endfor
    for k = 1:numel (T)
      name = T(k).name;
      assert (! isempty (T(k).help) && ! isempty (T(k).range), name);
      if (any (strcmp (name, derived)))
        continue;
      endif
      if (isfield (user_name, name))
        name = user_name.(name);
      endif
      [item, position] = help_item (help_text, name);
      if (isempty (item))
        error ("option '%s' of %s is not documented in the help of %s",
               name, gw, strjoin (fronts, ", "));
      endif
      stated = stated_default (item, position);
      if (! isempty (stated) && ! strcmp (T(k).default, "(required)"))
        assert (same_default (stated, T(k).default),
                sprintf ("%s: the help says default %s, the core %s", name,
                         stated, T(k).default));
        compared++;
      endif
    endfor
    ## an option the table does not declare is refused
    fail_id = [fname ":badOption"];
    try
      feval (gw, fname, 1, 1, 1, struct ("na", 1, "nb", 1, "nk", 0,
                                         "lambda_svf", 1, "not_an_option", 1));
      error ("the gateway accepted an unknown option");
    catch err
      assert (err.identifier, fail_id);
    end_try_catch
  endfor

  ## the parser above reads the defaults the help texts state (a floor, so
  ## that a change of wording cannot silently empty the check)
  assert (compared >= 5, sprintf ("only %d defaults compared", compared));

  check_output_error_options ();
  check_convergence_options ();
  check_frequency_options ();
  check_refined_iv_options ();
  check_tfsrivc_options ();
  check_tfcoe_options ();

  ## Given explicitly at the table's default, each option changes nothing.
  T = riv_mex ("rsrivc", "options");
  default_of = @(n) T(strcmp ({T.name}, n)).default;
  Ts = 0.05;
  u = prbs (9, 8);
  x = simc (struct ("B", 4, "F", [1 2.4 4]), u, Ts);
  randn ("state", 2);
  data = iddata (x + 0.05 * randn (size (x)), u, Ts, "InterSample", "zoh");
  base = {"lambda_svf", 3, "tsiv", 10};
  ref = rsrivc (data, [1 2 0], base{:});
  for name = {"stability", "prefilter", "svf", "adm", "dtupdate", ...
              "covariance_guard", "adg", "antiwindup"}
    v = default_of (name{1});
    num = str2double (v);
    if (strcmp (v, "true"))
      v = true;
    elseif (! isnan (num))
      v = num;
    endif
    thm = rsrivc (data, [1 2 0], base{:}, name{1}, v);
    assert (isequal (thm, ref), sprintf ("%s at its default changed THM",
                                         name{1}));
  endfor
  ## antiwindup_lambda acts only with conditional updating
  w = {"antiwindup", 1e3};
  a = rsrivc (data, [1 2 0], base{:}, w{:});
  b = rsrivc (data, [1 2 0], base{:}, w{:}, "antiwindup_lambda",
              str2double (default_of ("antiwindup_lambda")));
  assert (isequal (a, b));
  c = rsrivc (data, [1 2 0], base{:}, w{:}, "antiwindup_lambda", 0.9);
  assert (! isequal (a, c));
endfunction

## The output-error family: the defaults its help texts and option sets
## state are the table's, giving them explicitly changes nothing, and the
## gateway refuses an option the table does not declare.
function check_output_error_options ()
  T = pem_mex ("oe", "options");
  assert (isstruct (T) && numel (T) >= 10);
  for k = 1:numel (T)
    assert (! isempty (T(k).help) && ! isempty (T(k).range), T(k).name);
  endfor
  default_of = @(n) str2double (T(strcmp ({T.name}, n)).default);
  maxiter = default_of ("maxiter");
  tol = default_of ("tol");
  ## the help texts that state them
  [item, pos] = help_item (get_help_text ("tfcoe"), "MaxIter");
  assert (same_default (stated_default (item, pos), num2str (maxiter)));
  [item, pos] = help_item (get_help_text ("tfcoe"), "TolPar");
  t = regexp (item, 'Default ([-+0-9.eE]+[0-9])', "tokens", "once");
  assert (! isempty (t) && same_default (t{1}, num2str (tol)));
  for f = {"oeOptions", "tfestOptions"}
    h = get_help_text (f{1});
    t = regexp (h, '@code\{MaxIterations\} ([0-9]+).*@code\{Tolerance\} ([-+0-9.eE]+[0-9])',
                "tokens", "once");
    assert (numel (t) == 2, [f{1} ": the help states no default"]);
    assert (same_default (t{1}, num2str (maxiter)), [f{1} ": MaxIterations"]);
    assert (same_default (t{2}, num2str (tol)), [f{1} ": Tolerance"]);
    o = feval (f{1});
    assert (o.SearchOptions.MaxIterations, maxiter);
    assert (o.SearchOptions.Tolerance, tol);
  endfor
  h = get_help_text ("oe");
  t = regexp (h, 'MaxIterations\}, default ([0-9]+)', "tokens", "once");
  assert (! isempty (t) && same_default (t{1}, num2str (maxiter)));
  ## explicit defaults change nothing
  Ts = 0.05;
  u = prbs (8, 4);
  randn ("state", 3);
  y = simc (struct ("B", 2, "F", [1 1.2 1]), u, Ts);
  data = iddata (y + 0.02 * randn (size (y)), u, Ts);
  a = tfest (data, 2, 0);
  b = tfest (data, 2, 0, "MaxIterations", maxiter, "Tolerance", tol);
  assert (isequal (getpvec (a), getpvec (b)));
  warning ("off", "all", "local");       # MaxIter 0: "not converged"
  c = tfest (data, 2, 0, "MaxIterations", 0);   # the start, not the optimum
  assert (! isequal (getpvec (a), getpvec (c)));
  ## an undeclared option is refused by the gateway
  try
    pem_mex ("oe", y, u, Ts, struct ("model", "oe_ct", "nf", 2, "nb", 1,
                                     "not_an_option", 1));
    error ("pem_mex accepted an unknown option");
  catch err
    assert (err.identifier, "oe:badOption");
  end_try_catch
endfunction

## The convergence detector's options (rlsconverge, "tsiv", "auto"): the
## defaults rlsconverge's help states are the table's, and the run reports
## the table's defaults as the settings it used.
function check_convergence_options ()
  T = rlssvf_mex ("rlsconverge", "converge", "options");
  assert (isstruct (T) && numel (T) >= 6);
  h = get_help_text ("rlsconverge");
  for name = {"nblocks", "alpha", "eyfloor", "tol_theta", "ptol"}
    core = T(strcmp ({T.name}, name{1})).default;
    [item, pos] = help_item (h, name{1});
    assert (same_default (stated_default (item, pos), core),
            "rlsconverge: %s", name{1});
  endfor
  Ts = 0.05;
  u = prbs (9, 8);
  y = simc (struct ("B", 4, "F", [1 2.4 4]), u, Ts);
  [~, info] = rlsconverge (iddata (y, u, Ts), [2 1 0], "lambda_svf", 3);
  for name = {"nblocks", "alpha", "eyfloor", "tol_theta", "ptol"}
    core = str2double (T(strcmp ({T.name}, name{1})).default);
    assert (info.(name{1}), core, 1e-12 * abs (core));
  endfor
endfunction

## The frequency-domain family: the defaults tffsrivc's help states are
## the table's, giving them explicitly changes nothing, and the gateway
## refuses an option the table does not declare.
function check_frequency_options ()
  T = freq_srivc_mex ("tffsrivc", "options");
  assert (isstruct (T) && numel (T) >= 10);
  for k = 1:numel (T)
    assert (! isempty (T(k).help) && ! isempty (T(k).range), T(k).name);
  endfor
  shown = @(n) T(strcmp ({T.name}, n)).default;
  default_of = @(n) str2double (shown (n));
  h = get_help_text ("tffsrivc");
  for pair = {"NumTd", "num_td"; "MaxIter", "maxiter"; "TolPar", "tol"}.'
    pattern = sprintf ('@code\\{%s\\}\\s*\\(([-+0-9.eE]+)\\)', pair{1});
    t = regexp (h, pattern, "tokens", "once");
    assert (! isempty (t), "tffsrivc: the help states no default of %s",
            pair{1});
    assert (same_default (t{1}, shown (pair{2})), pair{1});
  endfor
  w = logspace (-1, 1, 40)';
  G = idfrd (2 ./ ((1i * w) .^ 2 + 1.2i * w + 1) .* exp (-0.3i * w), w,
             "Ts", 0);
  a = tffsrivc (G, 2, 0);
  b = tffsrivc (G, 2, 0, "NumTd", default_of ("num_td"), "MaxIter",
                default_of ("maxiter"), "Tol", default_of ("tol"));
  assert (isequal (getpvec (a), getpvec (b)));
  try
    freq_srivc_mex ("tffsrivc", w, ones (40, 1), [],
                    struct ("na", 2, "nb", 1, "not_an_option", 1));
    error ("freq_srivc_mex accepted an unknown option");
  catch err
    assert (err.identifier, "tffsrivc:badOption");
  end_try_catch
endfunction

## The refined-IV families (core/include/ctid/offline/refined_iv_options.hpp):
## refined_iv_mex (srivc and the engine's other front-ends) and rivc_mex
## (rivc, clrivc, cl2srivc, tfrivc). The options a user sets are documented
## with the table's defaults (a front-end's word for a default: TimeScale
## "auto" is 0, InitialState "zero" false), giving the defaults explicitly
## changes nothing, and an option the table does not declare is refused.
function check_refined_iv_options ()
  ## table name: the user's name, and the front-end's word for the default
  engine = struct ("tol", "Tol", "maxiter", "MaxIter",
                   "max_starts", "MaxStarts", "time_scale", "TimeScale",
                   "initial_state", "InitialState",
                   "output_offset", "OutputOffset", "cutoffs", "lambda");
  bj = struct ("tol", "Tol", "maxiter", "MaxIter",
               "arma_maxiter", "ArmaMaxIter", "arma_method", "ArmaMethod",
               "cutoffs", "lambda");
  user = {"refined_iv_mex", "srivc", engine; "rivc_mex", "rivc", bj};
  words = struct ("auto", "0", "zero", "false");
  compared = 0;
  for f = 1:rows (user)
    [gw, fname, names] = user{f, :};
    T = feval (gw, fname, "options");
    assert (isstruct (T) && numel (T) >= 15);
    text = get_help_text (fname);
    for k = 1:numel (T)
      assert (! isempty (T(k).help) && ! isempty (T(k).range), T(k).name);
      if (! isfield (names, T(k).name))
        continue;                  # set from nn, the data or another option
      endif
      [item, position] = help_item (text, names.(T(k).name));
      assert (! isempty (item), sprintf ("%s: %s is not documented", fname,
                                         names.(T(k).name)));
      stated = stated_default (item, position);
      if (isfield (words, stated))
        stated = words.(stated);
      endif
      if (! isempty (stated))
        assert (same_default (stated, T(k).default),
                sprintf ("%s: the help says default %s, the core %s",
                         names.(T(k).name), stated, T(k).default));
        compared++;
      endif
    endfor
  endfor
  assert (compared >= 8, sprintf ("only %d defaults compared", compared));
  ## the positional tol and maxiter of clrivc and cl2srivc
  T = rivc_mex ("rivc", "options");
  for f = {"clrivc", "cl2srivc"}
    t = regexp (get_help_text (f{1}),
                '@var\{tol\} \(([-+0-9.eE]+)\).*@var\{maxiter\} \(([0-9]+)',
                "tokens", "once");
    assert (numel (t) == 2, [f{1} ": the help states no default"]);
    assert (same_default (t{1}, T(strcmp ({T.name}, "tol")).default));
    assert (same_default (t{2}, T(strcmp ({T.name}, "maxiter")).default));
  endfor

  ## explicit defaults change nothing; another value does
  Ts = 0.05;
  u = prbs (8, 4);
  randn ("state", 4);
  y = simc (struct ("B", 2, "F", [1 1.2 1]), u, Ts);
  data = iddata (y + 0.02 * randn (size (y)), u, Ts);
  T = refined_iv_mex ("srivc", "options");
  v = @(n) str2double (T(strcmp ({T.name}, n)).default);
  a = srivc (data, [1 2 0]);
  b = srivc (data, [1 2 0], "Tol", v ("tol"), "MaxIter", v ("maxiter"),
             "MaxStarts", v ("max_starts"), "TimeScale", v ("time_scale"));
  assert (isequal (getpvec (a), getpvec (b)));
  warning ("off", "all", "local");     # MaxIter 1: "not converged"
  c = srivc (data, [1 2 0], "MaxIter", 1);
  assert (! isequal (getpvec (a), getpvec (c)));
  T = rivc_mex ("rivc", "options");
  v = @(n) T(strcmp ({T.name}, n)).default;
  a = rivc (data, [1 1 1 2 0]);
  b = rivc (data, [1 1 1 2 0], "Tol", str2double (v ("tol")),
            "MaxIter", str2double (v ("maxiter")),
            "ArmaMaxIter", str2double (v ("arma_maxiter")),
            "ArmaMethod", v ("arma_method"));
  assert (isequal (getpvec (a), getpvec (b)));
  c = rivc (data, [1 1 1 2 0], "ArmaMethod", "ivarma");
  assert (! isequal (getpvec (a), getpvec (c)));

  ## an undeclared option is refused by the gateways
  for g = {"refined_iv_mex", "srivc"; "rivc_mex", "rivc"}.'
    try
      feval (g{1}, g{2}, y, u, Ts, [], struct ("nf", 2, "nb", 1,
                                               "not_an_option", 1));
      error ("%s accepted an unknown option", g{1});
    catch err
      assert (err.identifier, [g{2} ":badOption"]);
    end_try_catch
  endfor
endfunction

## CONTSID's tfsrivc defaults, declared in tfsrivc_options.hpp: the ones
## tfsrivc's help states, each read in the help's own wording.
function check_tfsrivc_options ()
  T = refined_iv_mex ("tfsrivc", "tf_options", "options");
  assert (isstruct (T) && numel (T) >= 12);
  for k = 1:numel (T)
    assert (! isempty (T(k).help) && ! isempty (T(k).range), T(k).name);
  endfor
  default_of = @(n) T(strcmp ({T.name}, n)).default;
  text = regexprep (get_help_text ("tfsrivc"), '\s+', " ");
  stated = {"tdmin", 'NumTd range and grid [^(]*\(default ([-+0-9.eE]+);';
            "numtd", '; ([0-9]+) points\)';
            "maxiter", '@item MaxIter [^(]*\(([0-9]+)\)';
            "tolpar", 'below TolPar \(([-+0-9.eE]+)\)';
            "tolfun", 'below TolFun \(([-+0-9.eE]+)\)';
            "stepreduction", 'convention, default ([-+0-9.eE]+)\)';
            "focusorder", 'order FocusOrder \(default ([0-9]+)\)';
            "fixtd", "keep the delay \\(default '(on|off)'\\)";
            "integration", "s = 0\\); default '(on|off)'"};
  check_stated_defaults ("tfsrivc", text, stated, default_of);

  ## the defaults tfsrivc_init's and tfrivc's helps state are the table's
  ## too (they take tfsrivc's options)
  others = {"tfsrivc_init", "tdmin", ...
            '@code\{TdMax\} \(the delay range, default ([-+0-9.eE]+) and';
            "tfsrivc_init", "numtd", ...
            '@code\{NumTd\} \(grid size, default ([0-9]+)';
            "tfrivc", "focusorder", ...
            'order @code\{FocusOrder\}, default ([0-9]+)\)'};
  for k = 1:rows (others)
    t = regexp (regexprep (get_help_text (others{k, 1}), '\s+', " "),
                others{k, 3}, "tokens", "once");
    assert (numel (t) == 1, sprintf ("%s: the help states no default of %s",
                                     others{k, 1}, others{k, 2}));
    assert (same_default (t{1}, default_of (others{k, 2})),
            sprintf ("%s: the help says %s %s, the core %s", others{k, 1},
                     others{k, 2}, t{1}, default_of (others{k, 2})));
  endfor

  ## explicit defaults change nothing; another value does
  Ts = 0.05;
  u = prbs (8, 4);
  M0 = idtf (4, [1 1.2 4], "IODelay", 0.37);
  y = simc (M0, iddata ([], u, Ts, "InterSample", "zoh"));
  randn ("state", 5);
  data = iddata (y + 0.02 * randn (size (y)), u, Ts, "InterSample", "zoh");
  v = @(n) str2double (default_of (n));
  a = tfsrivc (data, 2, 0, 0.3, "TdMax", 1);
  b = tfsrivc (data, 2, 0, 0.3, "TdMax", 1, "TdMin", v ("tdmin"),
               "NumTd", v ("numtd"), "MaxIter", v ("maxiter"),
               "TolPar", v ("tolpar"), "TolFun", v ("tolfun"),
               "StepReduction", v ("stepreduction"), "FixTd", "off",
               "Integration", "off");
  assert (isequal ([getpvec(a); a.IODelay], [getpvec(b); b.IODelay]));
  c = tfsrivc (data, 2, 0, 0.3, "TdMax", 1, "TolPar", 0.1);
  assert (! isequal ([getpvec(a); a.IODelay], [getpvec(c); c.IODelay]));

  ## an undeclared option is refused by the gateway
  try
    refined_iv_mex ("tfsrivc", "tf_options", struct ("tdmax", 1, "bogus", 1));
    error ("refined_iv_mex accepted an unknown option");
  catch err
    assert (err.identifier, "tfsrivc:badOption");
  end_try_catch
endfunction

## tfcoe's CONTSID delay-search options are read by the same table as
## tfsrivc's (tfsrivc_options.hpp): the defaults tfcoe's help states are
## the table's.
function check_tfcoe_options ()
  T = refined_iv_mex ("tfcoe", "tf_options", "options");
  default_of = @(n) T(strcmp ({T.name}, n)).default;
  text = regexprep (get_help_text ("tfcoe"), '\s+', " ");
  stated = {"tdmin", '@item TdMin Lower bound [^(]*\(s, default ([0-9.]+)\)';
            "numtd", '@item NumTd [^(]*\(default ([0-9]+);';
            "stepreduction", 'convention, default ([0-9.]+)\); a value';
            "focusorder", 'integer 1\.\.10 \(default ([0-9]+)\)';
            "integration", 'Default @qcode\{"(on|off)"\}\. Not applicable'};
  check_stated_defaults ("tfcoe", text, stated, default_of);
endfunction

## Each row of STATED names a table option and the pattern that reads its
## default from TEXT, FNAME's help with its white space folded; the default
## read there, in the help's own wording ('on' and 'off' for true and
## false), is the table's (DEFAULT_OF (name), as text).
function check_stated_defaults (fname, text, stated, default_of)
  words = struct ("on", "true", "off", "false");
  for k = 1:rows (stated)
    t = regexp (text, stated{k, 2}, "tokens", "once");
    assert (numel (t) == 1, sprintf ("%s: the help states no default of %s",
                                     fname, stated{k, 1}));
    v = t{1};
    if (isfield (words, v))
      v = words.(v);
    endif
    assert (same_default (v, default_of (stated{k, 1})),
            sprintf ("%s: the help says %s %s, the core %s", fname,
                     stated{k, 1}, v, default_of (stated{k, 1})));
  endfor
endfunction

## The @item block of the help text that names option NAME (an item may
## name several, "@item th0, P0": POSITION is NAME's place among them), up
## to the next @item or @end table.
function [item, position] = help_item (text, name)
  item = "";
  position = 0;
  starts = regexp (text, '@item\s', "start");
  ends = [starts(2:end), numel(text) + 1];
  for k = 1:numel (starts)
    block = text(starts(k):ends(k) - 1);
    first = strtok (block, "\n");
    names = regexp (first(6:end), '[A-Za-z_]\w*', "match");
    position = find (strcmp (names, name), 1);
    if (! isempty (position))
      stop = strfind (block, "@end table");
      if (! isempty (stop))
        block = block(1:stop(1) - 1);
      endif
      item = block;
      return;
    endif
  endfor
  position = 0;
endfunction

## The default an @item block states for its POSITION-th name, as text:
## "(default 0.998", '@qcode{"keep"} (default)' or "true (default)"; empty
## when it states none in those forms.
function v = stated_default (item, position)
  v = "";
  marks = regexp (item, '\(default', "start");
  if (numel (marks) < position)
    return;
  endif
  ## the text from the previous default statement on
  from = 1;
  if (position > 1)
    from = marks(position - 1) + 1;
  endif
  part = item(from:end);
  t = regexp (part, '^[^(]*?\(default:?\s+([-+0-9.eE]+)[,;)\s]', "tokens", "once");
  if (isempty (t))
    t = regexp (part, '\(default:?\s+([-+0-9.eE]+)[,;)\s]', "tokens", "once");
    if (position > 1 && ! isempty (t))
      t = {};                            # that one belongs to a later name
    endif
  endif
  if (! isempty (t))
    v = t{1};
    return;
  endif
  t = regexp (part, '@qcode\{"([^"]+)"\}\s*\(default\)', "tokens", "once");
  if (! isempty (t))
    v = t{1};
    return;
  endif
  t = regexp (part, '\<(true|false)\s*\(default\)', "tokens", "once");
  if (! isempty (t))
    v = t{1};
  endif
endfunction

function tf = same_default (stated, core)
  a = str2double (stated);
  b = str2double (core);
  if (! isnan (a) && ! isnan (b))
    tf = abs (a - b) <= 1e-12 * max (1, abs (b));
  else
    tf = strcmp (stated, core);
  endif
endfunction

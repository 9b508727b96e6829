## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn  {} {@var{start} =} contsid_init_method (@var{fname}, @var{init}, @var{layout})
## @deftypefnx {} {@var{start} =} contsid_init_method (@var{fname}, @var{init}, @var{layout}, @var{refused}, @var{why})
## @deftypefnx {} {[@var{theta0}, @var{start}] =} contsid_init_method (@var{fname}, @var{start}, @var{layout}, @var{y}, @var{W}, @var{t})
## The one reader of the start method (@code{InitMethod},
## @code{init_method}) of the refined-IV family (srivc, clsrivc, rivc,
## tfrivc, clrivc, cl2srivc, hsrivc, hrivc, hwsrivc), and the start it
## names. @var{fname} is the public caller (every error identifier starts
## with it).
##
## First form: reads @var{init} and returns @var{start}, a struct with
## @code{Method} (@qcode{"sriv"}, @qcode{"ivgpmf"}, @qcode{"lssvf"} or
## @qcode{"model"}), @code{Requested} (the name given, or
## @qcode{"model"}), @code{Theta} (a given model's [f b], else []),
## @code{Lambda} ([]) and @code{Stabilised} (false). The names:
## @table @asis
## @item @qcode{"sriv"}, @qcode{"srivc"} or [] (default)
## the engine's own start (IVSVF at a grid of cut-offs, then SRIVC from
## the best starts; the SRIVC start of the RIVC family).
## @item @qcode{"ivgpmf"}, @qcode{"ivsvf"}
## one IVSVF estimate (thesis eqs. 2.4-2.7), the filter
## (lambda/(p + lambda))^n being CONTSID's Poisson-moment functionals.
## @item @qcode{"lssvf"}
## one LSSVF estimate (thesis eq. 1.32).
## @item an @code{idpoly}/@code{idtf} or numeric [f b]
## that model; it must be stable (@var{fname}:badInput otherwise).
## @end table
## @var{layout} holds @code{nf} (per denominator) and @code{nb} (per
## channel), which fix the number of values of [f b]. @var{refused}, a
## cellstr of the methods the caller cannot honour, raises
## @var{fname}:notSupported with the reason @var{why}. Any other name
## raises @var{fname}:badOption listing the valid ones.
##
## Second form: the start itself. @var{layout} is the engine's struct of
## @code{contsid_refined_iv} (@code{nf}, @code{nb}, @code{nk},
## @code{group}, @code{intersample}, @code{delay}, @code{output_offset},
## @code{cutoffs}); @var{y}, @var{W}, @var{t} the record as for
## @code{contsid_refined_iv}. @qcode{"sriv"} returns [] (the caller's
## engine starts itself); a model returns its [f b]; @qcode{"lssvf"} and
## @qcode{"ivgpmf"} run the core's one-step LSSVF / IVSVF
## (@code{contsid_refined_iv}, as @code{lssvf} and @code{ivsvf} do) at
## @code{cutoffs} when given, else at the engine's automatic cut-off:
## the one of 12 log-spaced between 5/T and 0.5 pi/Ts whose estimate
## has the smallest simulation error (@code{start.Lambda} says which). An
## unstable estimate is not used as it is: its roots in the closed right
## half-plane are reflected into the left one (p -> -conj (p); a root on
## the imaginary axis moves to -1e-6 max (1, |p|)), with the warning
## @var{fname}:unstableStart, and @code{start.Stabilised} is true.
## @var{theta0} is a row [f b] (empty for @qcode{"sriv"}).
## @end deftypefn

function [out1, out2] = contsid_init_method (fname, init, layout, varargin)
  if (nargin <= 5)
    out1 = read_start (fname, init, layout, varargin{:});
    return;
  endif
  [out1, out2] = compute_start (fname, init, layout, varargin{:});
endfunction

function start = read_start (fname, init, layout, refused = {}, why = "")
  names = {"sriv", "srivc", "ivgpmf", "ivsvf", "lssvf"};
  canonical = {"sriv", "sriv", "ivgpmf", "ivgpmf", "lssvf"};
  start = struct ("Method", "sriv", "Requested", "sriv", "Theta", [],
                  "Lambda", [], "Stabilised", false);
  if (isempty (init))
    return;
  endif
  if (ischar (init) && rows (init) <= 1)
    k = find (strcmpi (init, names));
    if (isempty (k))
      error ([fname ":badOption"],
             ["%s: unknown InitMethod '%s'; valid: 'sriv' ('srivc'), ", ...
              "'ivgpmf' ('ivsvf'), 'lssvf', an idpoly or [f b]"],
             fname, init);
    endif
    start.Method = canonical{k};
    start.Requested = names{k};
    if (any (strcmp (start.Method, refused)))
      error ([fname ":notSupported"],
             "%s: InitMethod '%s' is not supported: %s", fname, init, why);
    endif
    return;
  endif
  if (! isnumeric (init) && ! isa (init, "idpoly") && ! isa (init, "idtf"))
    error ([fname ":badOption"],
           ["%s: InitMethod must be 'sriv' ('srivc'), 'ivgpmf' ('ivsvf'), ", ...
            "'lssvf', an idpoly or [f b]"], fname);
  endif
  if (any (strcmp ("model", refused)))
    error ([fname ":notSupported"],
           "%s: an initial model is not supported: %s", fname, why);
  endif
  np = sum (layout.nf) + sum (layout.nb);
  theta = model_theta (init, np);
  if (! isnumeric (theta) || ! isreal (theta) || numel (theta) != np
      || any (! isfinite (theta(:))))
    error ([fname ":badOption"],
           ["%s: InitMethod must be 'sriv', 'ivgpmf', 'lssvf', an idpoly ", ...
            "or %d values [f b] ([f_1 .. f_m b_1 .. b_m] for m ", ...
            "denominators)"], fname, np);
  endif
  theta = double (theta(:).');
  at = cumsum ([0, layout.nf(:).']);
  for g = 1:numel (layout.nf)
    if (any (real (roots ([1, theta(at(g)+1:at(g+1))])) >= 0))
      error ([fname ":badInput"], "%s: the initial model must be stable",
             fname);
    endif
  endfor
  start.Method = "model";
  start.Requested = "model";
  start.Theta = theta;
endfunction

## [f b] of an idpoly/idtf start (one input: F and B normalised by F(1);
## several: the model's own [f b] order), or the numbers themselves.
function theta = model_theta (init, np)
  theta = init;
  if (isa (init, "idtf"))
    init = idpoly (init);
  endif
  if (isa (init, "idpoly"))
    F = init.F;
    B = init.B;
    if (! iscell (F) && ! iscell (B) && ! isempty (F) && F(1) != 0)
      theta = [F(2:end) / F(1), B / F(1)];
    else
      theta = init.theta;
    endif
    if (numel (theta) != np)
      theta = init.theta;
    endif
  elseif (! isnumeric (init) || ! isvector (init))
    theta = NaN;
  endif
endfunction

function [theta0, start] = compute_start (fname, start, e, y, W, t)
  theta0 = [];
  switch (start.Method)
    case "sriv"
      return;
    case "model"
      theta0 = start.Theta;
      return;
  endswitch
  o = struct ("method", start.Method, "nf", e.nf, "nb", e.nb);
  if (strcmp (start.Method, "ivgpmf"))
    o.method = "ivsvf";
  endif
  for f = {"group", "nk", "delay", "intersample", "y_intersample", ...
           "integrators", "output_offset"}
    if (isfield (e, f{1}) && ! isempty (e.(f{1})))
      o.(f{1}) = e.(f{1});
    endif
  endfor
  if (isfield (e, "cutoffs") && ! isempty (e.cutoffs))
    o.cutoffs = e.cutoffs;
  endif
  [theta, ~, info] = contsid_refined_iv (fname, y, W, t, o);
  np = sum (e.nf) + sum (e.nb);
  theta0 = theta(1:np).';
  at = cumsum ([0, e.nf(:).']);
  reflected = {};
  for g = 1:numel (e.nf)
    f = theta0(at(g)+1:at(g+1));
    r = roots ([1, f]);
    bad = real (r) >= 0;
    if (any (bad))
      reflected{end+1} = mat2str (r(bad).', 4);
      r(bad) = complex (-abs (real (r(bad))), imag (r(bad)));
      zero = bad & real (r) == 0;
      r(zero) = complex (-1e-6 * max (1, abs (r(zero))), imag (r(zero)));
      theta0(at(g)+1:at(g+1)) = real (poly (r))(2:end);
    endif
  endfor
  start.Lambda = info.cutoff;
  start.Theta = theta0;
  if (! isempty (reflected))
    start.Stabilised = true;
    warning ([fname ":unstableStart"],
             ["%s: the %s start (lambda = %g) is unstable; its poles %s ", ...
              "were reflected into the left half-plane"], fname,
             upper (start.Method), start.Lambda, strjoin (reflected, ", "));
  endif
endfunction

%!test  # the names and their canonical methods
%! L = struct ("nf", 2, "nb", 1);
%! s = contsid_init_method ("srivc", [], L);
%! assert (s.Method, "sriv");
%! s = contsid_init_method ("srivc", "IVSVF", L);
%! assert ({s.Method, s.Requested}, {"ivgpmf", "ivsvf"});
%! s = contsid_init_method ("srivc", "srivc", L);
%! assert (s.Method, "sriv");
%! s = contsid_init_method ("srivc", [3 2 1], L);
%! assert ({s.Method, s.Theta}, {"model", [3 2 1]});

%!test  # the LSSVF start is lssvf's estimate; an unstable one is reflected
%! randn ("state", 1);
%! Ts = 0.05; u = kron (sign (randn (40, 1)), ones (25, 1));
%! y = simc (idctm (4, [1 2.4 4]), u, Ts);
%! L = struct ("nf", 2, "nb", 1, "nk", 0, "intersample", "zoh");
%! L.cutoffs = 3;
%! s = contsid_init_method ("srivc", "lssvf", L);
%! [th, s] = contsid_init_method ("srivc", s, L, y, u, Ts);
%! M = lssvf (iddata (y, u, Ts), [2 1 0], 3);
%! assert (th, M.theta, 1e-12);
%! assert (s.Lambda, 3);
%! assert (! s.Stabilised);
%! y2 = y + 0.01 * (1:numel (y))' .^ 2;   # drives LSSVF unstable
%! s = contsid_init_method ("srivc", "lssvf", L);
%! lastwarn ("");
%! [th, s] = contsid_init_method ("srivc", s, L, y2, u, Ts);
%! [~, id] = lastwarn ();
%! assert (id, "srivc:unstableStart");
%! assert (s.Stabilised);
%! assert (all (real (roots ([1 th(1:2)])) < 0));

%!error id=srivc:badOption contsid_init_method ("srivc", "magic", struct ("nf", 2, "nb", 1))
%!error id=srivc:badOption contsid_init_method ("srivc", [1 2], struct ("nf", 2, "nb", 1))
%!error id=srivc:badOption contsid_init_method ("srivc", {1}, struct ("nf", 2, "nb", 1))
%!error id=srivc:badInput contsid_init_method ("srivc", [-1 4 4], struct ("nf", 2, "nb", 1))
%!error id=hwsrivc:notSupported contsid_init_method ("hwsrivc", "lssvf", struct ("nf", 2, "nb", 1), {"lssvf"}, "no")
%!error id=hwsrivc:notSupported contsid_init_method ("hwsrivc", [1 2 3], struct ("nf", 2, "nb", 1), {"model"}, "no")

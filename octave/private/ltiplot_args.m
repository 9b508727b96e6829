## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {[@var{systems}, @var{styles}, @var{range}, @var{opt}] =} @
##   ltiplot_args (@var{who}, @var{args})
## Read the arguments of @code{bodeplot} and @code{stepplot}:
## @code{(sys1, [style1], sys2, [style2], @dots{}, [range], [opt])}.
##
## Each model is returned as a control-package LTI object: an @code{lti}
## as it is, any other object through @code{tf (model)} (the model
## classes' conversion), else through @code{frd (model)}, else as
## @code{frd (model.ResponseData, model.Frequency, model.Ts)} (SITB's
## @code{idfrd} properties).  A string after a
## model is its line style: @var{styles}@{k@} is @code{@{style@}} or
## @code{@{@}}, to pass on as @code{plot (x, y, styles@{k@}@{:@})}.
## @var{range} is the numeric (or cell
## @code{@{wmin, wmax@}}) argument after the models, @code{[]} when
## absent; @var{opt} a trailing options struct (one without a
## @code{ResponseData} field, which marks frequency response data),
## @code{[]} when absent.
## Errors are @code{@var{who}:badInput}.
## @end deftypefn

function [systems, styles, range, opt] = ltiplot_args (who, args)
  if (! exist ("tf"))
    error ([who, ":notSupported"],
           "%s: needs the control package (pkg load control)", who);
  endif
  systems = {};
  styles = {};
  range = [];
  opt = [];
  k = 1;
  while (k <= numel (args))
    x = args{k};
    if (ischar (x))
      if (isempty (systems) || ! isempty (styles{end}) || ! isempty (range))
        error ([who, ":badInput"],
               "%s: argument %d: a line style must follow a model", who, k);
      endif
      [~, valid] = __pltopt__ ("plot", x, false);
      if (! valid)
        error ([who, ":badInput"],
               "%s: argument %d: '%s' is not a line style", who, k, x);
      endif
      styles{end} = {x};
    elseif (isstruct (x) && ! isfield (x, "ResponseData"))
      if (k != numel (args))
        error ([who, ":badInput"],
               "%s: the options struct must be the last argument", who);
      endif
      opt = x;
    elseif (isnumeric (x) || iscell (x))
      if (! isempty (range))
        error ([who, ":badInput"],
               "%s: argument %d: only one frequency or time argument", who, k);
      endif
      range = x;
    elseif (! isempty (range))
      error ([who, ":badInput"],
             ["%s: argument %d: models must come before the frequencies ", ...
              "or times"],
             who, k);
    else
      systems{end+1} = to_lti (who, x, k);
      styles{end+1} = {};
    endif
    k++;
  endwhile
  if (isempty (systems))
    error ([who, ":badInput"], "%s: no model to plot", who);
  endif
endfunction

function sys = to_lti (who, x, k)
  if (isa (x, "lti"))
    sys = x;
    return;
  endif
  try
    sys = tf (x);
    return;
  catch
  end_try_catch
  try
    sys = frd (x);
    return;
  catch
  end_try_catch
  try
    ## frequency response data with SITB's property names (idfrd)
    sys = frd (x.ResponseData, x.Frequency, x.Ts);
    return;
  catch
  end_try_catch
  error ([who, ":badInput"],
         "%s: argument %d: a %s is not a model that tf () or frd () converts",
         who, k, class (x));
endfunction

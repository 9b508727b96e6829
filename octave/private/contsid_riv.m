## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {[@var{thm}, @var{yh}, @var{pset}, @var{info}] =} contsid_riv (@var{fname}, @var{nout}, @dots{})
## Shared back-end of rivsvf, rsrivc, clrivsvf and clrsrivc: parses the
## data, @var{nn} and the options, reorders between the public parameter
## order ([a b] for the SVF methods, [b f] for the SRIVC ones) and the
## core's [a b], and calls the compiled gateway for @var{nout} outputs.
## @end deftypefn

function varargout = contsid_riv (fname, nout, varargin)
  p = contsid_riv_args (fname, fname, varargin{:});
  outs = cell (1, max (1, min (nout, 4)));
  try
    [outs{:}] = riv_mex (fname, p.data{:}, p.opts);
  catch err
    contsid_rethrow (err);
  end_try_catch
  perm = p.perm;
  outs{1} = outs{1}(:, perm);
  if (numel (outs) >= 3)
    outs{3} = outs{3}(perm, perm, :);
  endif
  if (numel (outs) >= 4)
    outs{4}.tsiv = p.tsiv;
    outs{4}.tsiv_detector = p.tsiv_detector;
  endif
  varargout = contsid_expand (outs, p.d);
  contsid_check_track (fname, varargout);
endfunction

## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn  {} {@var{data} =} relay (@var{num}, @var{den}, @var{Ts})
## @deftypefnx {} {@var{data} =} relay (@var{num}, @var{den}, @var{Ts}, @var{name}, @var{value}, @dots{})
## Relay-feedback test (as CONTSID's @code{relay}): the plant
## G(s) = num(s)/den(s) e^(-s IODelay) in the loop u = relay (r - y),
## r = 0, sampled every @var{Ts}: at each instant t_k the relay reads the
## measured output and sets u_k = up if -y_k > vp, un if -y_k < vn, and
## keeps its value in between (hysteresis); u is held (ZOH) until t_(k+1).
## The plant is simulated exactly (matrix exponential of the augmented
## state). Returns the sustained oscillation as @code{iddata (y, u, Ts)}
## with InterSample @qcode{"zoh"}: @code{NumCycle} whole limit cycles
## starting at the upward switch of cycle @code{StartCycle}.
##
## Options: @code{Amp} = [up un] (default [1 -1]); @code{Hyst} = [vp vn]
## (default 0.1 [up un]); @code{NumCycle} (40); @code{StartCycle} (7);
## @code{IODelay} (0, a multiple of Ts); @code{SNR} in dB (default Inf:
## no noise), white Gaussian noise on the measured output, inside the loop,
## with variance var(y) 10^(-SNR/10) of the noise-free oscillation;
## @code{IntSamp} @qcode{"on"} (default: y_k is the mean of y over
## (t_(k-1), t_k], integrated sampling) or @qcode{"off"} (y_k = y(t_k)).
## The plant must be strictly proper and oscillate in the loop: without
## an upward switch for 2e4 samples, or after 2e5 samples in all, the
## error is @code{relay:notConverged}.
## @seealso{tffsrivc, tffcoe}
## @end deftypefn

function varargout = relay (varargin)
  varargout = contsid_guard ("relay", @relay_body, nargout, varargin);
endfunction

function [data, varargout] = relay_body (varargin)
  contsid_nargchk ("relay", nargin, nargout, [3 Inf], 1);
  [num, den, Ts] = deal (varargin{1:3});
  if (! isnumeric (num) || ! isnumeric (den) || ! isvector (num)
      || ! isvector (den) || ! isreal (num) || ! isreal (den)
      || any (! isfinite ([num(:); den(:)])) || isempty (den) || den(1) == 0)
    error ("relay:badInput",
           "relay: num and den must be finite real vectors, den(1) != 0");
  endif
  if (! isnumeric (Ts) || ! isscalar (Ts) || ! (Ts > 0) || ! isfinite (Ts))
    error ("relay:badInput", "relay: Ts must be a positive scalar");
  endif
  num = double (num(:).');
  den = double (den(:).');
  num = num(find (num != 0, 1):end);
  n = numel (den) - 1;
  if (n < 1 || numel (num) > n)
    error ("relay:badInput", "relay: the plant must be strictly proper");
  endif
  opts = contsid_options ("relay", struct ("Amp", [1 -1], "Hyst", [],
                                           "NumCycle", 40, "StartCycle", 7,
                                           "IODelay", 0, "SNR", Inf,
                                           "IntSamp", "on"),
                          varargin(4:end));
  amp = opts.Amp;
  if (! isnumeric (amp) || numel (amp) != 2 || ! (amp(1) > amp(2)))
    error ("relay:badOption", "relay: Amp must be [up un] with up > un");
  endif
  hyst = opts.Hyst;
  if (isempty (hyst))
    hyst = 0.1 * amp;
  endif
  if (! isnumeric (hyst) || numel (hyst) != 2 || hyst(1) < hyst(2))
    error ("relay:badOption", "relay: Hyst must be [vp vn] with vp >= vn");
  endif
  for name = {"NumCycle", "StartCycle"}
    v = opts.(name{1});
    if (! isnumeric (v) || ! isscalar (v) || v < 1 || v != round (v))
      error ("relay:badOption", "relay: %s must be an integer >= 1",
             name{1});
    endif
  endfor
  nd = opts.IODelay / Ts;
  if (! isscalar (nd) || ! (nd >= 0) || abs (nd - round (nd)) > 1e-9)
    error ("relay:badOption",
           "relay: IODelay must be a non-negative multiple of Ts");
  endif
  nd = round (nd);
  if (! isscalar (opts.SNR) || isnan (opts.SNR))
    error ("relay:badOption", "relay: SNR must be a scalar (dB)");
  endif
  if (! ischar (opts.IntSamp) || ! any (strcmpi (opts.IntSamp, {"on", "off"})))
    error ("relay:badOption", "relay: IntSamp must be 'on' or 'off'");
  endif
  intsamp = strcmpi (opts.IntSamp, "on");

  ## Controllable canonical form with the output integral as last state.
  a = den / den(1);
  c = zeros (1, n);
  c(n - numel (num) + 1:n) = num / den(1);
  A = [zeros(n - 1, 1) eye(n - 1); -fliplr(a(2:end))];
  B = [zeros(n - 1, 1); 1];
  C = fliplr (c);
  Aa = [A zeros(n, 1); C 0];
  Ba = [B; 0];
  E = expm ([Aa Ba; zeros(1, n + 2)] * Ts);
  Phi = E(1:n+1, 1:n+1);
  Gam = E(1:n+1, end);

  [y, u] = simulate (0);
  if (isfinite (opts.SNR))
    sd = std (y) * 10 ^ (-opts.SNR / 20);
    [y, u] = simulate (sd);
  endif
  data = iddata (y, u, Ts, "InterSample", "zoh");

  function [y, u] = simulate (sd)
    total = opts.StartCycle + opts.NumCycle;
    ## a budget of samples: at most 2e5, and 2e4 without a switch
    limit = 2e5;
    quiet = 2e4;
    x = zeros (n + 1, 1);
    ys = zeros (1024, 1);
    us = zeros (1024, 1);
    state = amp(1);
    edges = [];
    zprev = 0;
    buffer = zeros (nd + 1, 1);
    k = 0;
    while (numel (edges) < total + 1)
      k++;
      last = 0;
      if (! isempty (edges))
        last = edges(end);
      endif
      if (k > limit || k - last > quiet)
        error ("relay:notConverged", ["relay: no sustained oscillation "
               "(%d samples, %d since the last switch)"], k, k - last);
      endif
      if (intsamp)
        yk = (x(end) - zprev) / Ts;
        if (k == 1)
          yk = C * x(1:n);
        endif
      else
        yk = C * x(1:n);
      endif
      yk += sd * randn ();
      e = -yk;
      previous = state;
      if (e > hyst(1))
        state = amp(1);
      elseif (e < hyst(2))
        state = amp(2);
      endif
      if (state > previous)
        edges(end+1) = k;
      endif
      if (k > numel (ys))
        ys(2 * k) = 0;
        us(2 * k) = 0;
      endif
      ys(k) = yk;
      us(k) = state;
      buffer = [state; buffer(1:end-1)];
      zprev = x(end);
      x = Phi * x + Gam * buffer(end);
    endwhile
    idx = edges(opts.StartCycle + 1):(edges(total + 1) - 1);
    y = ys(idx);
    u = us(idx);
  endfunction
endfunction

%!test  # a limit cycle: whole periods, u only takes the relay levels
%! d = relay (1, [1 2 1], 0.01, "IODelay", 0.5, "NumCycle", 5, "StartCycle", 3);
%! u = d.u;
%! assert (all (u == 1 | u == -1));
%! assert (u(1) == 1 && u(end) == -1);
%! up = find (diff (u) > 0);
%! assert (numel (up), 4);
%! assert (max (abs (d.y)) > 0.1);

%!test  # the oscillation is that of the plant: the period matches the
%! ## describing-function estimate within 10 % (phase -pi at the crossover)
%! d = relay (1, [1 2 1], 0.005, "IODelay", 0.5, "Hyst", [0 0], "IntSamp", "off");
%! up = find (diff (d.u) > 0);
%! P = mean (diff (up)) * 0.005;
%! wu = fzero (@(w) -2 * atan (w) - 0.5 * w + pi, 1.5);
%! assert (abs (P - 2 * pi / wu) / (2 * pi / wu) < 0.1);

%!error id=relay:badInput relay (1, [1 2 1])
%!error id=relay:badInput relay ([1 1 1], [1 2 1], 0.01)
%!error id=relay:badInput relay (1, [1 2 1], -1)
%!error id=relay:badInput relay (1, [0 0], 0.1)
%!error id=relay:badOption relay (1, [1 2 1], 0.01, "Amp", [-1 1])
%!error id=relay:badOption relay (1, [1 2 1], 0.01, "Hyst", [-1 1])
%!error id=relay:badOption relay (1, [1 2 1], 0.01, "NumCycle", 0)
%!error id=relay:badOption relay (1, [1 2 1], 0.01, "IODelay", 0.005)
%!error id=relay:badOption relay (1, [1 2 1], 0.01, "IntSamp", "x")
%!error id=relay:badOption relay (1, [1 2 1], 0.01, "SNR", NaN)
%!error id=relay:badOption relay (1, [1 2 1], 0.01, "Bogus", 1)
%!error id=relay:badInput [a, b] = relay (1, [1 2 1], 0.01)
%!error id=relay:notConverged relay (1, [1 2 1], 0.01, "Hyst", [5 -5])

%!demo
%! data = relay (1, [1 2 1], 0.01, "IODelay", 0.5, "SNR", 20);
%! plot (data);
%! M = tffsrivc (data, 2, 0)

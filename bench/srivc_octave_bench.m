## -*- texinfo -*-
## @deftypefn {} {@var{T} =} srivc_octave_bench (@var{old_octave_dir})
## Side-by-side timing of @code{srivc} with its automatic start on 100 000
## samples: this tree's engine against an older tree's front-end (issue 9
## bar: at least 5 times faster than main's 4.2 s). @var{old_octave_dir} is
## the @file{octave/} folder of the other tree with its gateways built,
## e.g.
## @example
## git archive main octave | tar -x -C /tmp/old   # then build its MEX
## octave-cli -q --eval "addpath octave bench; srivc_octave_bench ('/tmp/old/octave')"
## @end example
## Both are called through their private back-end
## (@code{contsid_offline ("srivc", @{data, nn@})}), each in its own
## octave-cli process started by this function, on the same record: a second-order system [1 2 0] (ZOH PRBS input, 10 %
## output noise) and a fourth-order lightly damped one [2 4 0]. Each is
## run 3 times and the median kept. Returns a struct array with the
## times, the estimates and the ratio.
## @end deftypefn

function T = srivc_octave_bench (old_dir)
  here = fileparts (fileparts (mfilename ("fullpath")));
  new_dir = fullfile (here, "octave");
  N = 100000;
  Ts = 0.01;
  randn ("state", 11);
  rand ("state", 11);
  u = kron (sign (randn (N / 10, 1)), ones (10, 1));
  cases = {[1 2 0], idctm(4, [1 2.4 4]); ...
           [2 4 0], idctm([0.5 40], conv([1 0.4 4], [1 1 25]))};
  T = struct ("nn", {}, "old", {}, "new", {}, "ratio", {}, "old_F", {},
              "new_F", {});
  for c = 1:rows (cases)
    [nn, M0] = cases{c, :};
    x = simc (M0, u, Ts);
    y = x + 0.1 * std (x) * randn (N, 1);
    data = iddata (y, u, Ts, "InterSample", "zoh");
    [t_old, M_old] = timed (old_dir, data, nn);
    [t_new, M_new] = timed (new_dir, data, nn);
    T(end+1) = struct ("nn", nn, "old", t_old, "new", t_new,
                       "ratio", t_old / t_new, "old_F", M_old.F,
                       "new_F", M_new.F);
    printf ("srivc %s on %d samples: old %.3f s, new %.3f s, ratio %.1f\n",
            mat2str (nn), N, t_old, t_new, t_old / t_new);
    printf ("  true F %s\n  old  F %s\n  new  F %s\n", mat2str (M0.F, 5),
            mat2str (M_old.F, 5), mat2str (M_new.F, 5));
  endfor
endfunction

## Times contsid_offline ("srivc", {data, nn}) of the tree `dir` in its own
## octave-cli process (two trees' functions of the same names cannot share
## one session), on the record saved to a temporary file.
function [t, M] = timed (dir, data, nn)
  file = [tempname() ".mat"];
  out = [tempname() ".mat"];
  y = get (data, "OutputData");
  u = get (data, "InputData");
  Ts = get (data, "Ts");
  save ("-binary", file, "y", "u", "Ts", "nn");
  script = sprintf (["addpath ('%s'); cd ('%s'); load ('%s'); ", ...
                     "d = iddata (y, u, Ts, 'InterSample', 'zoh'); ", ...
                     "warning ('off', 'all'); times = zeros (1, 3); ", ...
                     "for k = 1:3, tic; M = contsid_offline ('srivc', ", ...
                     "{d, nn}); times(k) = toc; end; F = M.F; ", ...
                     "save ('-binary', '%s', 'times', 'F');"],
                    dir, fullfile (dir, "private"), file, out);
  [status, text] = system (sprintf ("octave-cli -q --eval \"%s\"", script));
  if (status != 0)
    error ("srivc_octave_bench: the run in %s failed:\n%s", dir, text);
  endif
  r = load (out);
  delete (file);
  delete (out);
  t = median (r.times);
  M = struct ("F", r.F);
endfunction

## -*- texinfo -*-
## @deftypefn {} {} test_frozen_model_kernels ()
## YH of @code{[thm, yh] = rlssvf (...)} (the frozen model's output,
## eq. 1.60) on the fixed-size path (the series of CompanionZohAdvance,
## companion_kernels.hpp) against the gateway's dynamic-size reference
## (option kernels = "dynamic": a matrix exponential per sample) and against
## a plain-Octave simulation of the frozen models from THM (expm of the
## augmented matrix per sample), na = 1..4, one and two inputs (one
## delayed), on a record with a gap (irregular intervals).  Errors on the
## first failure:
## @example
## octave --no-gui -q --eval "addpath octave tests/octave; test_frozen_model_kernels"
## @end example
## The private folder (the gateway) is put on the path for the duration of
## the test.
## @end deftypefn

function test_frozen_model_kernels ()
  root = fileparts (fileparts (fileparts (mfilename ("fullpath"))));
  private_dir = fullfile (root, "octave", "private");
  addpath (private_dir);
  cleanup = onCleanup (@() rmpath (private_dir));
  rand ("state", 14);
  randn ("state", 14);
  Ts = 0.1;
  A = {2, [2.4 4], [3 7 5], [3.2 8.4 10.4 8]};
  N = 1500;
  for na = 1:4
    for nu = 1:2
      u = 2 * mod (cumsum (rand (N, nu) < 0.1), 2) - 1;
      y = filter (0.1, [1 -0.9], u(:, 1)) + 0.02 * randn (N, 1);
      if (nu == 2)
        y += filter (0.05, [1 -0.8], [0; 0; u(1:end-2, 2)]);
      endif
      t = Ts * (1:N).';
      t(800:end) += 0.35;  # a gap: one interval of 0.45 s
      nb = [na, 1](1:nu);
      nk = [0, 2](1:nu);
      data = iddata (y, u, Ts, "InterSample", "zoh");
      p = contsid_rlssvf_args ("rlssvf", y, u, t, [na nb nk],
                               "lambda_svf", 3, "adm", "kf",
                               "adg", 1e-4 * eye (na + sum (nb)));
      opts = p.opts;
      opts.kernels = "fixed";
      [thm, yh] = rlssvf_mex ("rlssvf", p.data{:}, opts);
      opts.kernels = "dynamic";
      [thm_d, yh_d] = rlssvf_mex ("rlssvf", p.data{:}, opts);
      what = sprintf ("na = %d, nu = %d", na, nu);
      assert (thm, thm_d, 1e-12 * max (abs (thm_d(:))));
      err = max (abs (yh - yh_d)) / max (abs (yh_d));
      assert (err <= 1e-12, "%s: yh fixed vs dynamic %.1e", what, err);
      ## plain Octave: the frozen model of each sample over its interval
      yo = frozen_model_output (thm, u, t, na, nb, nk);
      err = max (abs (yh - yo)) / max (abs (yo));
      assert (err <= 1e-10, "%s: yh vs plain Octave %.1e", what, err);
      printf ("%s: |yh - dynamic| %.1e, |yh - plain Octave| %.1e\n", what,
              max (abs (yh - yh_d)) / max (abs (yh_d)), err);
    endfor
  endfor
endfunction

## x(t_k) of the frozen model theta(t_k) advanced over (t_(k-1), t_k] from
## the state of the previous sample, input held (ZOH); at rest at t_1.
function yo = frozen_model_output (thm, u, t, na, nb, nk)
  [N, nu] = size (u);
  Z = zeros (na, nu);
  prev = zeros (1, nu);
  yo = zeros (N, 1);
  ud = u;
  for j = 1:nu
    ud(:, j) = [zeros(nk(j), 1); u(1:end-nk(j), j)];
  endfor
  for k = 1:N
    d = thm(k, 1:na);
    F = [zeros(na - 1, 1), eye(na - 1); -fliplr(d)];
    if (k > 1)
      E = expm ([F, [zeros(na - 1, 1); 1]; zeros(1, na + 1)] * (t(k) - t(k-1)));
      Z = E(1:na, 1:na) * Z + E(1:na, end) * prev;
    endif
    prev = ud(k, :);
    offset = na;
    for j = 1:nu
      w = [Z(:, j); prev(j) - fliplr(d) * Z(:, j)];
      b = thm(k, offset + (1:nb(j)));
      yo(k) += b * w(nb(j):-1:1);
      offset += nb(j);
    endfor
  endfor
endfunction

## Quick side-by-side of RSRIVC-KF end to end with per-sample refresh:
## rsrivc (...) with "kernels" "fixed" vs "dynamic" (1e5 samples, best of 3,
## interleaved) and the plain-Octave bench/rsrivc_plain_octave.m on the
## first 2000 samples, orders 1-4, with the largest relative differences
## fixed - dynamic and fixed - plain Octave. Run from anywhere:
##   nice octave-cli -q bench/rsrivc_kernels_quick.m
root = fileparts (fileparts (mfilename ("fullpath")));
addpath (fullfile (root, "octave"));
addpath (fullfile (root, "bench"));
N = 1e5; Nn = 2000; Ts = 0.1; rand ("state", 1); randn ("state", 2);
u = 2 * mod (cumsum (rand (N, 1) < 0.1), 2) - 1;
printf ("n  fixed dynamic f/d  plain fixed/plain |f-d| |f-plain|  (M samples/s)\n");
for n = 1:4
  if (n == 2) a = [1 2.4 4]; b0 = 4; else a = poly (-2 * ones (1, n)); b0 = 2 ^ n; end
  F = [zeros(n - 1, 1), eye(n - 1); -a(end:-1:2)];
  E = expm ([F, [zeros(n - 1, 1); 1]; zeros(1, n + 1)] * Ts);
  Phi = E(1:n, 1:n); Gam = E(1:n, n + 1); C = [b0 zeros(1, n - 1)];
  den = poly (Phi); num = poly (Phi - Gam * C) - den;
  y = filter (num, den, u) + 0.05 * randn (N, 1);
  data = iddata (y, u, Ts, "InterSample", "zoh");
  Qn = 1e-4 * eye (n + 1);
  o = {"lambda_svf", 3.2, "adm", "kf", "adg", Qn, "tsiv", 100};
  t = Inf (1, 2);
  for r = 1:3
    tic; thf = rsrivc (data, [1 n 0], o{:}, "kernels", "fixed"); t(1) = min (t(1), toc);
    tic; thd = rsrivc (data, [1 n 0], o{:}, "kernels", "dynamic"); t(2) = min (t(2), toc);
  end
  tic; thp = rsrivc_plain_octave (y(1:Nn), u(1:Nn), Ts, 3.2, Qn, 100); tp = toc;
  r = [N ./ t, Nn / tp] / 1e6;
  dfd = max (abs (thf(:) - thd(:))) / max (abs (thd(:)));
  dfp = max (max (abs (thf(1:Nn, :) - thp))) / max (abs (thp(:)));
  printf ("%d %6.3f %7.3f %4.2f %6.4f %11.0f %6.1e %6.1e\n", n, r(1), r(2),
          r(1) / r(2), r(3), r(1) / r(3), dfd, dfp);
end
printf ("load %s\n", fileread ("/proc/loadavg"));

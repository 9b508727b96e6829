## Quick side-by-side of rlssvf end to end, "kernels" "fixed" vs "dynamic",
## thm and [thm, yh], orders 1-4 (1e5 samples, best of 5, interleaved), and
## the largest relative difference of the two paths. Run from anywhere:
##   nice octave-cli -q bench/rlssvf_kernels_quick.m
## (it adds the worktree's octave/ to the path itself).
addpath (fullfile (fileparts (fileparts (mfilename ("fullpath"))), "octave"));
N = 1e5; Ts = 0.1; rand("state",1); randn("state",2);
u = 2*mod(cumsum(rand(N,1) < 0.1), 2) - 1;
printf("n  thm_fixed thm_dyn f/d  thmyh_fixed thmyh_dyn f/d  thm/thmyh(fixed) |f-d|thm |f-d|yh  (M samples/s, best of 5, interleaved)\n");
for n = 1:4
  if (n == 2) a = [1 2.4 4]; b0 = 4; else a = poly(-2*ones(1,n)); b0 = 2^n; end
  F = [zeros(n-1,1), eye(n-1); -a(end:-1:2)];
  E = expm([F, [zeros(n-1,1);1]; zeros(1,n+1)]*Ts);
  Phi = E(1:n,1:n); Gam = E(1:n,n+1); C = [b0 zeros(1,n-1)];
  den = poly(Phi); num = poly(Phi - Gam*C) - den;
  y = filter(num, den, u) + 0.05*randn(N,1);
  data = iddata(y, u, Ts, "InterSample", "zoh");
  o = {"lambda_svf", 3.2, "adm", "kf", "adg", 1e-4*eye(n+1)};
  t = Inf(1,4);
  for r = 1:5
    tic; thf = rlssvf(data,[n 1 0],o{:},"kernels","fixed"); t(1) = min(t(1),toc);
    tic; thd = rlssvf(data,[n 1 0],o{:},"kernels","dynamic"); t(2) = min(t(2),toc);
    tic; [thf2,yhf] = rlssvf(data,[n 1 0],o{:},"kernels","fixed"); t(3) = min(t(3),toc);
    tic; [thd2,yhd] = rlssvf(data,[n 1 0],o{:},"kernels","dynamic"); t(4) = min(t(4),toc);
  end
  r = N./t/1e6;
  dth = max(abs(thf(:)-thd(:)))/max(abs(thd(:)));
  dyh = max(abs(yhf(:)-yhd(:)))/max(abs(yhd(:)));
  printf("%d %9.3f %7.3f %4.2f %11.3f %9.3f %4.2f %16.2f %8.1e %8.1e\n", n, r(1), r(2), r(1)/r(2), r(3), r(4), r(3)/r(4), t(3)/t(1), dth, dyh);
end
printf("load %s\n", fileread("/proc/loadavg"));

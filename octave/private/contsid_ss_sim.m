## -*- texinfo -*-
## @deftypefn {} {@var{y} =} contsid_ss_sim (@var{a}, @var{b}, @var{c}, @var{d}, @var{u}, @var{t}, @var{intersample}, @var{nk})
## Output of the continuous-time state-space model x' = a x + b u,
## y = c x + d u, from rest, at the sampling instants of the input
## @var{u} (N-by-nu), exact for a piecewise constant (@qcode{"zoh"}) or
## piecewise linear (@qcode{"foh"}) input: each interval h is integrated
## with the matrix exponential of [a b 0; 0 0 I; 0 0 0] h (Van Loan),
## whose blocks give x(t+h) from x(t), u(t) and the input's slope.
## @var{t}: the sampling interval or the N instants.  @var{nk}: ny-by-nu
## input delays in samples.
## @end deftypefn

function y = contsid_ss_sim (a, b, c, d, u, t, intersample, nk)
  [N, nu] = size (u);
  ny = rows (c);
  if (isempty (nk))
    nk = zeros (ny, nu);
  endif
  y = zeros (N, ny);
  if (all (all (nk == nk(1, :))))
    groups = {1:ny};
  else
    groups = num2cell (1:ny);
  endif
  for g = 1:numel (groups)
    rows_ = groups{g};
    ud = u;
    for j = 1:nu
      k = nk(rows_(1), j);
      ud(:, j) = [zeros(k, 1); u(1:N-k, j)];
    endfor
    yg = simulate (a, b, c(rows_, :), d(rows_, :), ud, t, intersample);
    y(:, rows_) = yg;
  endfor
endfunction

function y = simulate (a, b, c, d, u, t, intersample)
  [N, nu] = size (u);
  n = rows (a);
  foh = strcmp (intersample, "foh");
  Mx = [a, b, zeros(n, nu); zeros(nu, n + nu), eye(nu);
        zeros(nu, n + 2 * nu)];
  if (isscalar (t))
    h = repmat (t, N - 1, 1);
  else
    h = diff (t(:));
  endif
  x = zeros (n, 1);
  X = zeros (n, N);
  last_h = NaN;
  for k = 1:N-1
    if (h(k) != last_h)
      E = expm (Mx * h(k));
      E11 = E(1:n, 1:n);
      E12 = E(1:n, n+1:n+nu);
      E13 = E(1:n, n+nu+1:end);
      last_h = h(k);
    endif
    s = zeros (nu, 1);
    if (foh)
      s = (u(k+1, :) - u(k, :)).' / h(k);
    endif
    x = E11 * x + E12 * u(k, :).' + E13 * s;
    X(:, k+1) = x;
  endfor
  y = (c * X).' + u * d.';
endfunction

## -*- texinfo -*-
## @deftypefn {} {@var{X} =} residtrace_free (@var{F}, @var{N}, @var{Ts})
## Free responses of the model 1/F(p) in observable canonical form (x1 =
## y, A = [-f, [I; 0]]): column k is the output at the N samples started
## from the k-th unit state with no input, y(t) = C expm (A t) e_k, by the
## exact one-step map expm (A Ts).
## @end deftypefn

function X = residtrace_free (F, N, Ts)
  F = F(:).' / F(1);
  n = numel (F) - 1;
  A = [-F(2:end)(:), eye(n, n-1)];
  Phi = expm (A * Ts);
  X = zeros (N, n);
  r = [1, zeros(1, n-1)];
  for t = 1:N
    X(t, :) = r;
    r = r * Phi;
    if (any (! isfinite (r)))
      break;
    endif
  endfor
endfunction

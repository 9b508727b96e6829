## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{v} =} get_prop (@var{M}, @var{name})
## The value of the property @var{name} (canonical spelling) of @var{M}.
## @end deftypefn

function v = get_prop (M, name)
  switch (name)
    case {"Ts", "TimeUnit", "InputDelay", "InputName", "InputUnit", ...
          "OutputName", "OutputUnit", "Name", "Notes", "UserData", ...
          "NoiseVariance"}
      v = M.(name);
      return;
    case "Report"
      v = M.Report;
      v.Parameters.ParVector = pvec_of (M);
      v.Parameters.FreeParCovariance = M.cov;
      return;
    case "Variable"
      v = "s";
      if (M.Ts > 0)
        v = merge (strcmp (M.kind, "idpoly"), "z^-1", "z");
      endif
      return;
  endswitch
  p = M.par;
  switch (M.kind)
    case "idpoly"
      switch (name)
        case {"B", "F"}
          v = p.(name);
          if (M.nu == 1)
            v = v{1};
          endif
        case "theta"
          v = M.legacy.theta;
          if (isempty (v))
            p = pvec_of (M);
            v = p(first_rows (legacy_order (M))).';
          endif
        case "covariance"
          v = M.legacy.covariance;
          if (isempty (v) && ! isempty (M.cov))
            k = first_rows (legacy_order (M));
            v = M.cov(k, k);
          endif
        case "nk"
          v = M.legacy.nk;
          if (isempty (v))
            v = delays_in_samples (M);
          endif
        case "noise_variance"
          v = M.NoiseVariance;
        case "method"
          v = lower (M.Report.Method);
        case "iterations"
          v = M.Report.Termination.Iterations;
          if (isempty (v))
            v = 0;
          endif
        case "converged"
          v = M.Report.Termination.Converged;
          if (isempty (v))
            v = true;
          endif
        case "InterSample"
          v = M.Report.DataUsed.InterSample;
          if (isempty (v))
            v = "zoh";
          endif
        otherwise
          v = p.(name);
      endswitch
    case "idproc"
      if (any (strcmp (name, {"Kp", "Tp1", "Tp2", "Tp3", "Tw", "Zeta", ...
                              "Td", "Tz"})))
        if (isfield (p.Structure, name))
          v = p.Structure.(name).Value;
        else
          v = NaN;
        endif
      else
        v = p.(name);
      endif
    otherwise
      v = p.(name);
  endswitch
endfunction

function nk = delays_in_samples (M)
  d = M.InputDelay(:).' + M.par.IODelay(1, :);
  if (M.Ts > 0)
    nk = d;
    lead = cellfun (@(b) max ([0, find(b != 0, 1) - 1]), M.par.B);
    nk += lead;
    return;
  endif
  Ts = M.Report.DataUsed.Ts;
  if (all (d == 0))
    nk = zeros (1, M.nu);
  elseif (isempty (Ts))
    error ("idpoly:badInput",
           ["idpoly: nk (delays in samples) needs the sampling interval ", ...
            "of the estimation data; read InputDelay (seconds)"]);
  else
    nk = round (d / Ts);
  endif
endfunction

## theta(i) is pvec(k(i)): the first parameter each column of T feeds.
function k = first_rows (T)
  [~, k] = max (T != 0, [], 1);
endfunction

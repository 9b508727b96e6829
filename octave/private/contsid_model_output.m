## -*- texinfo -*-
## @deftypefn {} {[@var{d}, @var{yhat}, @var{rest}] =} contsid_model_output (@var{fname}, @var{args})
## Shared by comparec and residc: reads the data and a model, given as an
## idctm / struct with B and F / control tf, or as a recursive estimate
## THM with its nn (and "order", "bf" for rsrivc's [b f]), and simulates
## the model on the data's input (for THM: the frozen model of each sample,
## parameters linear between samples). Returns the data struct, the
## simulated output and the remaining arguments.
## @end deftypefn

function [d, yhat, rest] = contsid_model_output (fname, args)
  if (numel (args) < 2)
    error ([fname ":badInput"], "%s: expected data and a model", fname);
  endif
  d = contsid_getdata (fname, args{1});
  M = args{2};
  rest = args(3:end);
  if (d.uniform)
    t = d.Ts;
  else
    t = d.t;
  endif
  try
    if (isnumeric (M))
      if (isempty (rest) || ! isnumeric (rest{1}))
        error ([fname ":badInput"], ...
               "%s: a recursive estimate THM needs its nn", fname);
      endif
      nn = rest{1};
      rest = rest(2:end);
      k = find (cellfun (@(a) ischar (a) && strcmpi (a, "order"), rest), 1);
      if (! isempty (k) && k < numel (rest) && strcmpi (rest{k+1}, "bf"))
        nb = nn(1); na = nn(2);
        nn(1:2) = [na nb];
        M = M(:, [nb+1:end, 1:nb]);
        rest(k:k+1) = [];
      endif
      if (rows (M) != rows (d.y))
        error ([fname ":dimensionMismatch"], ...
               "%s: THM must have one row per sample (%d)", fname, rows (d.y));
      endif
      yhat = simc (M, nn, d.u, t, "InterSample", d.intersample);
    elseif (isa (M, "idctm") || isstruct (M) || isa (M, "tf"))
      yhat = simc (M, d.u, t, "InterSample", d.intersample);
    else
      error ([fname ":badInput"], ...
             ["%s: the model must be an idctm, a struct with B and F, ", ...
              "a tf, or THM with nn"],
             fname);
    endif
  catch err
    if (strncmp (err.identifier, "simc:", 5))
      id = strrep (err.identifier, "simc:", [fname ":"]);
      msg = strrep (err.message, "simc:", [fname ":"]);
      error (struct ("message", msg, "identifier", id));
    endif
    rethrow (err);
  end_try_catch
endfunction

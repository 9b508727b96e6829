## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{txt} =} check_demo_outputs (@var{outdir}, @var{figs}, @var{table}, @var{strings})
## Helper of the demo script tests: asserts that each PNG of the cell
## @var{figs} exists in @var{outdir} and is not empty, that the Markdown
## table @var{table} exists and contains each string of @var{strings}
## (e.g. the thesis' values it must quote), and returns its text.
## @end deftypefn

function txt = check_demo_outputs (outdir, figs, table, strings)
  for i = 1:numel (figs)
    f = fullfile (outdir, figs{i});
    assert (exist (f, "file") == 2, "missing %s", f);
    d = dir (f);
    assert (d.bytes > 1000, "empty figure %s", f);
  endfor
  f = fullfile (outdir, table);
  assert (exist (f, "file") == 2, "missing %s", f);
  txt = fileread (f);
  for i = 1:numel (strings)
    assert (! isempty (strfind (txt, strings{i})), "%s lacks %s", table,
            strings{i});
  endfor
endfunction

## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## run_demo_test (check): the scaffolding every demo script test shares.
## Puts <root>/demos on the path, calls check (out, root) with a fresh
## temporary output folder `out` (root: the repository), and removes the
## folder afterwards, also when a check fails.
function run_demo_test (check)
  root = ctid_test_root ();
  addpath (fullfile (root, "demos"));
  out = tempname ();
  unwind_protect
    check (out, root);
  unwind_protect_cleanup
    if (exist (out, "dir"))
      confirm_recursive_rmdir (false, "local");
      rmdir (out, "s");
    endif
  end_unwind_protect
endfunction

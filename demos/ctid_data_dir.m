## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {[@var{dir}, @var{why}] =} ctid_data_dir ()
## @deftypefnx {} {[@var{dir}, @var{why}] =} ctid_data_dir (@var{record})
## The folder of the measured benchmark records (EMPS, Silverbox): the
## environment variable @env{CTID_DATA} when it is set, else
## @file{<repo>/../shared/data}. With @var{record} (@qcode{"emps"},
## @qcode{"silverbox"}) its subfolder. When that folder does not exist,
## @var{dir} is empty and @var{why} says which folder was looked for, so
## that a demo can say so and skip its measured part and a test can report
## itself as skipped. Every demo and test that reads these records finds
## them here.
##
## @example
## [d, why] = ctid_data_dir ("emps");
## if (isempty (d)), disp (why); else, s = load (fullfile (d, "DATA_EMPS.mat")); endif
## @end example
## @end deftypefn

function [dir, why] = ctid_data_dir (record = "")
  dir = getenv ("CTID_DATA");
  from = "CTID_DATA";
  if (isempty (dir))
    repo = fileparts (fileparts (mfilename ("fullpath")));
    dir = fullfile (repo, "..", "shared", "data");
    from = "the default location";
  endif
  if (! isempty (record))
    dir = fullfile (dir, record);
  endif
  why = "";
  if (! exist (dir, "dir"))
    why = sprintf (["measured records not found: no folder %s (%s; set ", ...
                    "CTID_DATA to the folder that holds emps/ and ", ...
                    "silverbox/)"], dir, from);
    dir = "";
  endif
endfunction

%!test
%! old = getenv ("CTID_DATA");
%! unwind_protect
%!   setenv ("CTID_DATA", tempname ());
%!   [d, why] = ctid_data_dir ("emps");
%!   assert (d, "");
%!   assert (! isempty (strfind (why, "CTID_DATA")));
%!   setenv ("CTID_DATA", tempdir ());
%!   assert (ctid_data_dir (), tempdir ());
%! unwind_protect_cleanup
%!   setenv ("CTID_DATA", old);
%! end_unwind_protect

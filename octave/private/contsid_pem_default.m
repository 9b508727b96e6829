## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{v} =} contsid_pem_default (@var{name})
## The default of the output-error option @var{name} (@qcode{"maxiter"},
## @qcode{"tol"}, ...) as the core declares it
## (core/include/ctid/offline/output_error_options.hpp, returned by
## @code{pem_mex ("oe", "options")}), as a number: the front-ends and the
## option sets of @code{oeOptions}/@code{tfestOptions} show and use this
## value instead of writing it again.
## @end deftypefn

function v = contsid_pem_default (name)
  persistent table;
  if (isempty (table))
    table = pem_mex ("oe", "options");
  endif
  k = find (strcmp ({table.name}, name));
  if (numel (k) != 1)
    error ("contsid_pem_default: no option '%s' in the core's table", name);
  endif
  v = str2double (table(k).default);
endfunction

%!assert (contsid_pem_default ("maxiter"), 100)
%!assert (contsid_pem_default ("tol"), 1e-8)
%!error <no option> contsid_pem_default ("not_an_option")

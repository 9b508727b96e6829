## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{stored} =} pack_userdata (@var{user}, @var{intersample})
## Store the inter-sample behaviour of an @code{iddata} set together with
## the user's own value @var{user} in the @code{userdata} field.
##
## For the default @qcode{"zoh"} the user's value is stored unchanged, so the
## object is field-for-field identical to one built by the control package.
## For @qcode{"foh"} or @qcode{"bl"} (or when @var{user} itself looks like
## the wrapper)
## the field holds the 1-by-1 struct
## @code{struct ("InterSample", @var{intersample}, "UserData", @var{user})}.
## @seealso{unpack_userdata}
## @end deftypefn

function stored = pack_userdata (userdata, intersample)
  [~, ~, looks_packed] = unpack_userdata (userdata);
  if (strcmp (intersample, "zoh") && ! looks_packed)
    stored = userdata;
  else
    stored = struct ("InterSample", intersample, "UserData", {userdata});
  endif
endfunction

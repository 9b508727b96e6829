## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {@var{stored} =} pack_userdata (@var{user}, @var{intersample}, @var{given})
## Store the inter-sample behaviour of an @code{iddata} set together with
## the user's own value @var{user} in the @code{userdata} field.
##
## For the default @qcode{"zoh"} (not @var{given}: default false) the
## user's value is stored unchanged, so the object is field-for-field
## identical to one built by the control package.
## For a @qcode{"zoh"} that was given, for @qcode{"foh"} or @qcode{"bl"}
## (or when @var{user} itself looks like the wrapper)
## the field holds the 1-by-1 struct
## @code{struct ("InterSample", @var{intersample}, "UserData", @var{user})}.
## @seealso{unpack_userdata}
## @end deftypefn

function stored = pack_userdata (userdata, intersample, given = false)
  [~, ~, looks_packed] = unpack_userdata (userdata);
  if (strcmp (intersample, "zoh") && ! given && ! looks_packed)
    stored = userdata;
  else
    stored = struct ("InterSample", intersample, "UserData", {userdata});
  endif
endfunction

## Copyright (C) the ctid authors
## SPDX-License-Identifier: BSD-3-Clause

## -*- texinfo -*-
## @deftypefn {} {[@var{user}, @var{is}, @var{packed}] =} unpack_userdata @
##   (@var{stored})
## Split the @code{userdata} field @var{stored} of an @code{iddata} set into
## the user's own value @var{user} and the inter-sample behaviour @var{is}
## (@qcode{"zoh"} when the field was not written by @code{pack_userdata},
## e.g. for objects built by the control package).  @var{packed} tells
## whether the field was a wrapper, i.e. whether InterSample was given
## (the default @qcode{"zoh"} is not wrapped).
## @seealso{pack_userdata}
## @end deftypefn

function [userdata, intersample, packed] = unpack_userdata (stored)
  packed = isstruct (stored) && isscalar (stored) ...
           && isequal (fieldnames (stored), {"InterSample"; "UserData"}) ...
           && ischar (stored.InterSample) ...
           && any (strcmp (stored.InterSample, {"zoh", "foh", "bl"}));
  if (packed)
    userdata = stored.UserData;
    intersample = stored.InterSample;
  else
    userdata = stored;
    intersample = "zoh";
  endif
endfunction

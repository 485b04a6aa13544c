#pragma once
// Conditional requests on entity tags (RFC 9110 13.1.2, If-None-Match), for the content-addressed
// preview PNGs: "*", a list of tags, and weak tags (W/"...") all count, compared weakly as 13.1.2 asks.

#include <string_view>

namespace softtune::http {

/// True when the If-None-Match field value `header` matches the current representation's entity tag
/// `etag` (a quoted tag, "\"abc\""): "*", or any listed tag equal to it once a W/ prefix is dropped from
/// both. A value that is not a list of entity tags matches nothing.
bool if_none_match(std::string_view header, std::string_view etag);

}  // namespace softtune::http

#pragma once
// Route patterns and matching. A pattern is a path whose segments are literals, a capture with an
// optional literal prefix/suffix ("{id}", "{n}.png"), or, as the last segment, "{name...}" which takes
// the rest of the path (the static page). Captures never match an empty segment.

#include <map>
#include <optional>
#include <string>
#include <string_view>

namespace softtune::http {

/// The captures of `pattern` in `path`, or nothing when it does not match.
std::optional<std::map<std::string, std::string>> match_route(std::string_view pattern, std::string_view path);

/// True for a pattern ending in a "{name...}" rest capture.
bool is_rest_pattern(std::string_view pattern);

}  // namespace softtune::http

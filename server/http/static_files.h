#pragma once
// The static page from web/: a request path becomes a file under the web root or a Problem. No path
// escapes the root: only plain segments of [A-Za-z0-9._-] are accepted (so "..", "%2e%2e", "..%2f",
// "%00", backslashes and hidden files are refused before the file system is asked), and the resolved
// path, symlinks followed, must still lie inside the root.

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

#include "http/http_types.h"

namespace softtune::http {

/// Content-Type for a file name's extension (".html" -> "text/html; charset=utf-8"); unknown
/// extensions are application/octet-stream.
std::string content_type_for(std::string_view file_name);

/// The file for the percent-decoded request `path` ("/" and directories mean their index.html).
/// Throws Problem 400 (field "path") for a refused path and 404 when there is no such file.
std::filesystem::path resolve_static_path(const std::filesystem::path& web_root, std::string_view path);

/// The strong validator of a file's bytes: the 64-bit FNV-1a hash of them in hex, quoted ("\"cbf29ce484222325\"").
std::string static_etag(std::string_view bytes);

/// An HTTP-date (RFC 9110 5.6.7 IMF-fixdate, "Sun, 06 Nov 1994 08:49:37 GMT") of a time in seconds since 1970.
std::string http_date(long long unix_seconds);

/// GET of a static file: 200 with its content type, bytes, ETag, Last-Modified and "Cache-Control:
/// no-cache" (a browser asks again each time, and gets a 304 while the file is the same), or 304 when
/// `if_none_match` (the request's If-None-Match) names its ETag; or the Problem of resolve_static_path.
HttpResponse serve_static(const std::filesystem::path& web_root, std::string_view path,
                          const std::optional<std::string>& if_none_match = std::nullopt);

}  // namespace softtune::http

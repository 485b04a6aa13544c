#pragma once
// The static page from web/: a request path becomes a file under the web root or a Problem. No path
// escapes the root: only plain segments of [A-Za-z0-9._-] are accepted (so "..", "%2e%2e", "..%2f",
// "%00", backslashes and hidden files are refused before the file system is asked), and the resolved
// path, symlinks followed, must still lie inside the root.

#include <filesystem>
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

/// GET of a static file: 200 with its content type and bytes, or the Problem of resolve_static_path.
HttpResponse serve_static(const std::filesystem::path& web_root, std::string_view path);

}  // namespace softtune::http

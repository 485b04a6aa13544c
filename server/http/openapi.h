#pragma once
// The OpenAPI 3.1 document (server/http/openapi.json), embedded into the binary at build time so the
// served document and the tests read the same bytes.

#include <string_view>

namespace softtune::http {

std::string_view openapi_text();

}  // namespace softtune::http

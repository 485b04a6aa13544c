#pragma once
// The OpenAPI 3.1 document: server/http/openapi.json, embedded into the binary at build time, with
// `info.x-softtune-limits` filled from the limits registry (http/limits_registry.h), so the served document
// and the tests read the same bytes and no limit is written in the JSON by hand.

#include <string_view>

namespace softtune::http {

std::string_view openapi_text();

}  // namespace softtune::http

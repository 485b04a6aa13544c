#pragma once
// The route table: one row per route (method, pattern, handler). A new capability adds one row here
// and its entry in openapi.json.

#include <functional>
#include <nlohmann/json.hpp>
#include <vector>

#include "http/service.h"

namespace softtune::http {

/// A handler for a JSON contract shared with the CLI (app::run_tune, ...): parses the body with
/// codec::parse_json (400 when malformed, deeper than limits::kMaxJsonDepth or holding a duplicated key),
/// runs `contract`, and answers 200 application/json. Problems it throws keep their status.
/// A deterministic contract names a `cache`: its responses are kept in the service's response cache,
/// keyed by the canonical request, and counted in softtune_cache_{hits,misses}_total{cache}.
Handler json_contract(std::function<nlohmann::json(const nlohmann::json&)> contract, std::string cache = "");

/// Every route of the service; the static page's catch-all comes last.
std::vector<Route> service_routes();

}  // namespace softtune::http

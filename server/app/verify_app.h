#pragma once
// The verify use case, shared by `softtune verify` and POST /api/v1/verify: tune, then run the tuning
// in each real engine asked for (none when the request names none), and answer per engine.

#include <nlohmann/json.hpp>

namespace softtune::app {

/// Decodes a verify request, runs it and encodes the answer; throws codec::Problem on bad input.
nlohmann::json run_verify(const nlohmann::json& request);

}  // namespace softtune::app

#pragma once
// The identify use case (issue 19), shared by `softtune identify` and POST /api/v1/identify: identify a
// recorded trajectory (core/identify.h); with the tune request it was tuned from, the error against it and
// what to type instead (core/identify_correction.h, and a modelled engine's `exact`).

#include <nlohmann/json.hpp>

namespace softtune::app {

/// Decodes an identify request, runs it and encodes the answer; throws codec::Problem on bad input.
nlohmann::json run_identify(const nlohmann::json& request);

}  // namespace softtune::app

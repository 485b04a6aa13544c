#pragma once
// The tune use case, shared by `softtune tune` and POST /api/v1/tune: a designer request in, the solver
// numbers, the discrete analysis and every engine's report out.

#include <nlohmann/json.hpp>

namespace softtune::app {

/// decode + tune + encode; throws codec::Problem on bad input.
nlohmann::json run_tune(const nlohmann::json& request);

}  // namespace softtune::app

#pragma once
// The cost of a verify request (request_cost.h), before any engine runs.

#include "app/request_cost.h"
#include "codec/verify_codec.h"

namespace softtune::app {

/// Each engine asked steps duration_s x fps x substeps times at 4 us a step (the four linked engines
/// averaged 2.8 us on one body, the rotating plank 3.3 us); the answer's trajectories are strided to
/// codec::kVerifyMaxPlotSamples, so its bytes stay small.
RequestCost verify_cost(const codec::VerifyRequest& q);

}  // namespace softtune::app

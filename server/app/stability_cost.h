#pragma once
// The cost of a stability request (request_cost.h), from its grid before the sweep runs.

#include <cstddef>

#include "app/request_cost.h"
#include "codec/stability_codec.h"

namespace softtune::app {

/// Cases of the chain: warm_start x mass_ratios x iterations x frequency_ratios (0 when it does not run).
std::size_t chain_case_count(const codec::StabilityRequest& q);

/// Sweep: per case 0.4 us of analysis and 30 ns per observed step (two states; 11-25 ns measured per
/// method, soft_exact the dearest), 10 us and 3 KiB to encode when the cases are listed. Chain: per case
/// 10 us and (15 iterations + 15) ns per step (13 ns per Gauss-Seidel iteration of the six unit states
/// measured at 64 iterations, 27 ns at one).
RequestCost stability_cost(const codec::StabilityRequest& q);

}  // namespace softtune::app

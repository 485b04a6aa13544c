#pragma once
// The identify answer's `correction` (docs/identify.md, "What to type instead"): what was typed and what to
// type next as frequency, ratio, k and c, where the rounds stand (the verdict and its sentence), the best
// round and what the model expects of `next`.

#include <cstddef>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>

#include "softtune/engines/engine_model.h"
#include "softtune/identify_correction.h"

namespace softtune::codec {

/// {frequency_hz, damping_ratio, k, c}: k = m omega^2, c = 2 m zeta omega with the request's mass (kg).
nlohmann::json response_json(const ResponseValues& v, double mass);

/// "converging", "met", "beyond_reach", "stalled".
std::string_view correction_verdict_name(CorrectionVerdict verdict);

/// The sentence for a correction verdict (docs/identify.md).
std::string correction_verdict_message(CorrectionVerdict verdict);

/// The `correction` object; `next_report` is the modelled engine's report for `next`, when there is one.
nlohmann::json correction_json(const Correction& correction, const ResponseValues& typed, std::size_t rounds,
                               double mass, const std::optional<engines::EngineReport>& next_report);

}  // namespace softtune::codec

#pragma once
// JSON of a preset's highest stable frequencies (`softtune stability --preset`, POST /api/v1/stability with
// `preset`); field list: docs/accuracy-and-stability.md "A preset's joints".

#include <nlohmann/json.hpp>
#include <string>

#include "softtune/diagnostics.h"
#include "softtune/scene/preset_stability.h"

namespace softtune::codec {

/// summary (passed: every asked frequency inside its limit), preset_limits (searched range, method, rows), stages.
nlohmann::json encode_preset_limits(const std::string& preset, const scene::PresetLimitSettings& settings,
                                    const scene::PresetStabilityResult& result, const StageList& stages);

}  // namespace softtune::codec

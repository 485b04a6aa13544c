#pragma once
// Writing core types as JSON. No NaN or infinity ever reaches the output: a value that is not finite
// is written as null, and callers document where null can appear.

#include <nlohmann/json.hpp>
#include <optional>

#include "softtune/diagnostics.h"
#include "softtune/engines/engine_model.h"
#include "softtune/warnings.h"

namespace softtune::codec {

nlohmann::json number_or_null(double v);
nlohmann::json number_or_null(const std::optional<double>& v);

/// [{code, message, value?, limit?}]
nlohmann::json warnings_json(const Warnings& warnings);

/// ["validate", "designer_mapping", ...]
nlohmann::json stages_json(const StageList& stages);

/// An engine's settings or parameters: {name: number, choice name, or true/false for a switch}.
nlohmann::json engine_values_json(const engines::Parameters& values);

/// {frequency_hz, damping_ratio, spectral_radius, stable} of an engine model's prediction.
nlohmann::json engine_prediction_json(const engines::Prediction& p);

}  // namespace softtune::codec

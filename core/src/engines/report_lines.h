#pragma once
// The report lines the closed-form models share (chipmunk.cpp, godot_2d.cpp, godot_3d.cpp): the plain export
// with its prediction, or its refusal; and the warning of an `exact` the engine cannot meet, with the
// nearest's errors. Internal to core/src/engines.

#include <cmath>
#include <numbers>
#include <optional>
#include <string_view>

#include "softtune/engines/engine_model.h"

namespace softtune::engines::report_lines {

/// `parameters` and `predicted` from the plain export's prediction (with engine_unstable when it grows), or,
/// when the engine refuses the values (no prediction), empty parameters and engine_refuses with `reason`.
inline void plain_export(EngineReport& out, const std::optional<Prediction>& p, Parameters parameters,
                         std::string_view engine, double refused_value, std::string_view reason) {
  if (p) {
    out.parameters = std::move(parameters);
    out.predicted = *p;
    if (!p->stable) out.warnings.push_back({WarningCode::engine_unstable, p->spectral_radius, 1.0, engine});
  } else {
    out.predicted = {std::nullopt, std::nullopt, 1.0, true};
    out.warnings.push_back({WarningCode::engine_refuses, refused_value, 0.0, engine, reason});
  }
}

/// engine_inexact with the nearest prediction's errors (frequency relative, damping ratio absolute; 0 when
/// there is none).
inline void inexact(EngineReport& out, const std::optional<Prediction>& nearest, const Target& t,
                    std::string_view engine, std::string_view reason) {
  const double asked_hz = t.omega / (2.0 * std::numbers::pi);
  const double frequency_error = nearest && nearest->frequency_hz ? *nearest->frequency_hz / asked_hz - 1.0 : 0.0;
  const double damping_error = nearest && nearest->damping_ratio ? *nearest->damping_ratio - t.damping_ratio : 0.0;
  out.warnings.push_back({WarningCode::engine_inexact, frequency_error, damping_error, engine, reason});
}

}  // namespace softtune::engines::report_lines

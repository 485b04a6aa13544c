#pragma once
// Input ranges for every request field. Each limit is named once here and documented in docs/api.md
// and docs/limits-and-security.md.

#include <optional>
#include <string>
#include <string_view>

#include "softtune/diagnostics.h"
#include "softtune/tune.h"

namespace softtune::limits {
inline constexpr double kMinFps = 1.0, kMaxFps = 100000.0;            ///< Hz
inline constexpr int kMaxSubsteps = 1000;
inline constexpr double kMaxStepRate = 1.0e6;                        ///< fps * substeps, Hz
inline constexpr double kMinFrames = 0.01, kMaxFrames = 1.0e6;       ///< response_frames
inline constexpr double kMaxFrequencyHz = 1.0e6;                     ///< Hz
inline constexpr double kMaxDampingRatio = 1000.0;
inline constexpr double kMinMass = 1.0e-9, kMaxMass = 1.0e12;        ///< kg, effective and body masses
inline constexpr double kMinInertia = 1.0e-12, kMaxInertia = 1.0e15;  ///< kg m^2
inline constexpr double kMaxCoordinate = 1.0e6;                      ///< m, |position| and |anchor|
inline constexpr double kMinAxisLength = 1.0e-9;                     ///< m, before normalizing
}  // namespace softtune::limits

namespace softtune {

/// Checks every range and the exactly-one-of pairs; the first violation, or nothing.
std::optional<FieldError> validate_tune_request(const TuneRequest& request);

/// The rule a FieldError states for a number outside [lo, hi]: "must be a finite number in [lo, hi] unit"
/// (the bounds as %g prints them; no unit, no trailing space). The scene checks state theirs the same way.
std::string finite_range_rule(double lo, double hi, std::string_view unit);

}  // namespace softtune

#pragma once
// Diagnostics returned as data (docs/conventions.md, "Diagnostics are data").

#include <string>
#include <string_view>
#include <vector>

namespace softtune {

enum class WarningCode {
  nyquist_clamped,         ///< exact mode: omega_d h > pi, clamped. value: asked Hz, limit: used Hz
  above_nyquist,           ///< standard mode: asked frequency above fps/2. value: Hz, limit: Nyquist Hz
  gamma_unrepresentable,   ///< exact mode, zeta = 0: c' + h k' = 0, report k', c' only
  exact_overflow,          ///< exact mode: k', c' overflow a double; standard softness used instead
  no_constraint,           ///< k = c = 0: the constraint does nothing
  few_steps_per_period,    ///< fewer than 4 steps per period (the talk's rule of thumb). value: steps
  frequency_error,         ///< standard mode misses the asked frequency by more than 5 %. value: relative
  axis_normalized,         ///< constraint axis was not unit length. value: its length
  box2d_v3_clamped,        ///< above Box2D v3's 0.25/h joint clamp. value: Hz asked, limit: Hz clamp
  mujoco_direct_solref,    ///< timeconst < 2h: MuJoCo would clamp it; the direct form is exported
  box2d_reduced_mass_error,  ///< b2LinearStiffness's reduced mass misses the frequency. value: relative
  engine_note,             ///< an engine cannot express this tuning exactly. text says which
  engine_refuses,          ///< the plain export is refused, replaced or divided by zero in the engine.
                           ///< detail: the engine's rule; value: the offending number
  engine_inexact,          ///< no parameters make the engine meet the request. value: the nearest's
                           ///< relative frequency error, limit: its damping ratio error; detail: why
  engine_unstable,         ///< the engine's step blows up with the plain export. value: spectral radius
};

struct Warning {
  WarningCode code;
  double value = 0.0;  ///< the offending value (units per code above)
  double limit = 0.0;  ///< the limit or the value used instead
  std::string_view engine = {};  ///< for engine warnings: which engine
  std::string_view detail = {};  ///< for engine warnings: the engine's rule, a static string
};

using Warnings = std::vector<Warning>;

/// snake_case code, e.g. "nyquist_clamped".
std::string_view warning_code_name(WarningCode code);

/// A sentence a designer can read, with the numbers and, where there is one, the fix.
std::string warning_message(const Warning& w);

}  // namespace softtune

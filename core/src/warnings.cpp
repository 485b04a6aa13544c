#include "softtune/warnings.h"

#include <fmt/format.h>

namespace softtune {

std::string_view warning_code_name(WarningCode code) {
  switch (code) {
    case WarningCode::nyquist_clamped: return "nyquist_clamped";
    case WarningCode::above_nyquist: return "above_nyquist";
    case WarningCode::gamma_unrepresentable: return "gamma_unrepresentable";
    case WarningCode::exact_overflow: return "exact_overflow";
    case WarningCode::no_constraint: return "no_constraint";
    case WarningCode::few_steps_per_period: return "few_steps_per_period";
    case WarningCode::frequency_error: return "frequency_error";
    case WarningCode::axis_normalized: return "axis_normalized";
    case WarningCode::box2d_v3_clamped: return "box2d_v3_clamped";
    case WarningCode::mujoco_direct_solref: return "mujoco_direct_solref";
    case WarningCode::box2d_reduced_mass_error: return "box2d_reduced_mass_error";
    case WarningCode::engine_note: return "engine_note";
    case WarningCode::engine_refuses: return "engine_refuses";
    case WarningCode::engine_inexact: return "engine_inexact";
    case WarningCode::engine_unstable: return "engine_unstable";
  }
  return "warning";
}

std::string warning_message(const Warning& w) {
  switch (w.code) {
    case WarningCode::nyquist_clamped:
      return fmt::format(
          "{:.6g} Hz is above what this time step can represent; exact mode clamped it to {:.6g} Hz "
          "(use more substeps or a higher fps to reach it)",
          w.value, w.limit);
    case WarningCode::above_nyquist:
      return fmt::format(
          "{:.6g} Hz is above the step's Nyquist frequency {:.6g} Hz: the solver cannot oscillate that "
          "fast (use more substeps or a higher fps)",
          w.value, w.limit);
    case WarningCode::gamma_unrepresentable:
      return "zero damping in exact mode needs c' + h k' = 0: gamma is unbounded, so use k' and c' as a "
             "symplectic spring (or ask for a small damping ratio)";
    case WarningCode::exact_overflow:
      return fmt::format("exact spring constants overflow (zeta omega h = {:.6g}): standard softness used instead",
                         w.value);
    case WarningCode::no_constraint:
      return "k = c = 0: this constraint applies no force at all";
    case WarningCode::few_steps_per_period:
      return fmt::format(
          "only {:.3g} steps per period (the rule of thumb is at least 4): explicit and "
          "semi-implicit springs go unstable here; use substeps or exact mode",
          w.value);
    case WarningCode::frequency_error:
      return fmt::format(
          "standard softness runs at {:.1f}% off the asked frequency at this step; use exact mode "
          "or more substeps",
          100.0 * w.value);
    case WarningCode::axis_normalized:
      return fmt::format("axis had length {:.6g} and was normalized", w.value);
    case WarningCode::box2d_v3_clamped:
      return fmt::format(
          "{:.6g} Hz is above Box2D v3's joint clamp of {:.6g} Hz (a quarter of the step rate): the "
          "joint's own rigid rows are softer than this spring there",
          w.value, w.limit);
    case WarningCode::mujoco_direct_solref:
      return fmt::format(
          "timeconst {:.6g} s is below MuJoCo's 2h = {:.6g} s safety limit: exported the direct "
          "(-stiffness, -damping) solref instead",
          w.value, w.limit);
    case WarningCode::box2d_reduced_mass_error:
      return fmt::format(
          "b2LinearStiffness's reduced mass ignores rotation: its springs run {:.1f}% off the asked "
          "frequency on this constraint",
          100.0 * w.value);
    case WarningCode::engine_note:
      return fmt::format("{} cannot express this tuning exactly", w.engine);
    case WarningCode::engine_refuses:
      return fmt::format("{}: the plain export ({:.6g}) is not what the engine runs: {}", w.engine, w.value, w.detail);
    case WarningCode::engine_inexact:
      return fmt::format(
          "{} cannot meet the request exactly ({}); the nearest it can runs {:+.2f}% off the "
          "frequency with damping ratio off by {:+.4f}",
          w.engine, w.detail, 100.0 * w.value, w.limit);
    case WarningCode::engine_unstable:
      return fmt::format(
          "{} blows up with the plain export (spectral radius {:.6g} per step): use its exact "
          "parameters, more substeps or a lower frequency",
          w.engine, w.value);
  }
  return "warning";
}

}  // namespace softtune

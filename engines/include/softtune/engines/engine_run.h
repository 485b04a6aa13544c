#pragma once
// One soft constraint in a real engine, built from softtune's answer alone (an EngineReport's `parameters`
// or `exact`, and its `settings`): the conformance tests and `softtune verify` run it and fit frequency and
// damping from the trajectory (fit_response, core/response_fit.h).

#include <string_view>
#include <vector>

#include "softtune/engines/engine_model.h"

namespace softtune::engines {

/// How the body hangs on the constraint.
enum class RunBody {
  point,           ///< a body of mass m_eff on the constraint's axis, rotation locked
  rotating_plank,  ///< a plank anchored off its centre (rotating_plank below): it turns as it swings
};

/// The plank of RunBody::rotating_plank: mass 2 m_eff, anchor `offset` from its centre perpendicular to the
/// constraint axis, inertia mass offset^2, so 1 / m_eff = 1 / mass + offset^2 / inertia (effective_mass.h).
struct PlankGeometry {
  double mass = 0.0;     ///< kg
  double inertia = 0.0;  ///< kg m^2 about its centre
  double offset = 0.0;   ///< m
};
inline PlankGeometry rotating_plank(double effective_mass) {
  const double mass = 2.0 * effective_mass, offset = 0.5;
  return {mass, mass * offset * offset, offset};
}

struct EngineRun {
  double effective_mass = 1.0;  ///< kg, what the report was computed for
  Parameters parameters;        ///< what to type: the report's `parameters` or `exact`
  SettingValues settings;       ///< the report's settings, indexed like the model's specs
  double dt = 1.0 / 60.0;       ///< s passed to each step call
  int steps = 600;              ///< step calls
  double x0 = 0.01;             ///< m (rad for an angular row), initial stretch, released from rest
  RunBody body = RunBody::point;
};

/// The stretch along the axis after each step call, x0 first (steps + 1 samples).
using RunTrajectory = std::vector<double>;

/// A real engine linked in process.
struct RealEngine {
  std::string_view name;     ///< the model's name (EngineModel::name)
  std::string_view version;  ///< the library version it was built against
  RunTrajectory (*run)(const EngineRun& run);
};

}  // namespace softtune::engines

#pragma once
// The integration methods softtune compares, and one step of any of them from a shared model.

#include <array>
#include <cstddef>
#include <string_view>

#include "softtune/exact_softness.h"
#include "softtune/integrators.h"

namespace softtune {

enum class Method { explicit_euler, semi_implicit_euler, implicit_euler, soft, soft_exact };
inline constexpr std::array<Method, 5> kAllMethods = {Method::explicit_euler, Method::semi_implicit_euler,
                                                      Method::implicit_euler, Method::soft, Method::soft_exact};

/// Where a method's result sits in anything indexed like kAllMethods (TuneResult::stability).
constexpr std::size_t method_index(Method m) { return static_cast<std::size_t>(m); }
static_assert([] {
  for (std::size_t i = 0; i < kAllMethods.size(); ++i) {
    if (method_index(kAllMethods[i]) != i) return false;
  }
  return true;
}(), "kAllMethods lists the methods in their enum order");

/// Stable snake_case name of a method ("explicit_euler", ..., "soft_exact"), used in every output.
std::string_view method_name(Method m);

/// Everything any method needs for one step of size h (s) of an oscillator with mass m (kg),
/// natural angular frequency omega (rad/s) and damping ratio zeta.
struct StepModel {
  double h = 1.0 / 60.0;  ///< s, the (sub)step
  Oscillator spring;      ///< m, k = m omega^2, c = 2 m zeta omega: the springs and implicit Euler
  Softness soft;          ///< standard softness of `spring` at h
  ExactSpring exact;      ///< k', c' and their softness at h
};
StepModel make_step_model(double mass, double omega, double zeta, double h);

/// The spring a method integrates: k', c' for soft_exact, (k, c) otherwise.
Oscillator method_spring(Method m, const StepModel& model);

/// One step of `m`. soft_exact with an unrepresentable gamma (zeta = 0) is a semi-implicit spring with
/// k' (docs/math.md: "a symplectic spring with corrected stiffness"), which is the limit of its soft step.
State step(Method m, State s, const StepModel& model);

}  // namespace softtune

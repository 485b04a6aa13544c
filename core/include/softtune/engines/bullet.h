#pragma once
// Bullet 3.24's soft 1-D constraint (btGeneric6DofSpring2Constraint: its spring, or ERP/CFM on a locked axis,
// solved by btSequentialImpulseConstraintSolver), modelled. Model in core/src/engines/bullet.cpp; the real
// engine runs it in tests/engines/bullet.

#include <string_view>

#include "softtune/engines/engine_model.h"

namespace softtune::engines {

extern const EngineModel kBulletModel;

/// The settings' indices in kBulletModel.settings.
inline constexpr std::size_t kBulletRouteSetting = 0;
inline constexpr std::size_t kBulletIterationsSetting = 1;
/// The route setting's choices.
inline constexpr double kBulletRouteSpring2 = 0.0;
inline constexpr double kBulletRouteErpCfm = 1.0;

/// The parameters' names (what to type), shared with the runner in engines/bullet.
inline constexpr std::string_view kBulletStiffness = "btGeneric6DofSpring2Constraint::setStiffness";
inline constexpr std::string_view kBulletDamping = "btGeneric6DofSpring2Constraint::setDamping";
inline constexpr std::string_view kBulletStiffnessLimit = "setStiffness(limitIfNeeded)";
inline constexpr std::string_view kBulletDampingLimit = "setDamping(limitIfNeeded)";
inline constexpr std::string_view kBulletStopErp = "btGeneric6DofSpring2Constraint::setParam(BT_CONSTRAINT_STOP_ERP)";
inline constexpr std::string_view kBulletStopCfm = "btGeneric6DofSpring2Constraint::setParam(BT_CONSTRAINT_STOP_CFM)";
/// The choices of the limitIfNeeded parameters.
inline constexpr std::string_view kBulletTrue = "true";
inline constexpr std::string_view kBulletFalse = "false";

/// setStiffness(.., limitIfNeeded = true) replaces k by m / (16 h^2) when sqrt(k / m) h exceeds this
/// (get_limit_motor_info2: "the spring should not be sampled faster that the quarter of its angular
/// frequency").
inline constexpr double kBulletSpringOmegaHLimit = 0.25;

/// The spring as get_limit_motor_info2 uses it after its limits.
struct BulletSpringInUse {
  double stiffness = 0.0;  ///< N/m
  double damping = 0.0;    ///< N s/m
  bool stiffness_limited = false;  ///< k was replaced by m / (16 h^2)
  bool damping_limited = false;    ///< c was replaced by m / h
};

/// get_limit_motor_info2's limits: with limit_stiffness, k -> m / (16 h^2) when 0.25 < sqrt(k / m) h; with
/// limit_damping, c -> m / h when c h > m. `body_mass` is the m Bullet computes there (1 / getInvMass() of
/// the dynamic body, mA mB / (mA + mB) for two), not the row's effective mass.
BulletSpringInUse bullet_spring_in_use(double body_mass, double stiffness, double damping, double h,
                                       bool limit_stiffness, bool limit_damping);

/// One world step of the spring2 route, on the row's (x, v): the solver reaches the row's target velocity
/// vel + f / m in its first iteration, f = -h (k x + c v), so v1 = v0 - (h / m)(k x0 + c v0), x1 = x0 + h v1
/// whatever the effective mass: semi-implicit Euler on (body_mass, k, c). Takes the spring in use.
Eigen::Matrix2d bullet_spring2_step_map(double body_mass, double stiffness, double damping, double h);

/// What n Gauss-Seidel iterations of one row with raw CFM c give of the converged impulse's row velocity
/// change: lambda_{j+1} = rhs - c lambda_j from 0, so lambda_n = rhs sum_{j<n} (-c)^j; the gain is that sum,
/// (1 - (-c)^n) / (1 + c), which tends to 1 / (1 + c) only for |c| < 1.
double bullet_cfm_gain(double cfm, int iterations);

/// One world step of the erp_cfm route on (x, v): v1 = (1 - g) v0 - g (ERP / h) x0, x1 = x0 + h v1, with
/// g = bullet_cfm_gain(CFM, iterations). Independent of the mass: the solver scales the row by its exact
/// effective mass (m_jacDiagABInv).
Eigen::Matrix2d bullet_erp_cfm_step_map(double erp, double cfm, int iterations, double h);

/// The CFM in [0, 1) whose gain over `iterations` is g (on the branch that starts at CFM 0), or empty when
/// no such CFM exists (g outside (0, 1], or below the least gain of an odd iteration count).
std::optional<double> bullet_cfm_for_gain(double gain, int iterations);

}  // namespace softtune::engines

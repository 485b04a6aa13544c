#pragma once
// ODE 0.16 (Debian's libode-dev 0.16.2, double precision): one soft joint row set by ERP and CFM, stepped
// by dWorldStep or dWorldQuickStep. Model in core/src/engines/ode.cpp; the real engine runs it in
// engines/ode and tests/engines/ode.

#include "softtune/engines/engine_model.h"

namespace softtune::engines {

extern const EngineModel kOdeModel;

/// Settings, indexed like kOdeModel.settings.
enum OdeSetting : int {
  kOdeStepper = 0,     ///< 0: dWorldStep (direct LCP), 1: dWorldQuickStep (SOR-LCP)
  kOdeIterations = 1,  ///< dWorldSetQuickStepNumIterations, default 20
  kOdeSorW = 2,        ///< dWorldSetQuickStepW, default 1.3
  kOdeJoint = 3,       ///< 0: dJointTypeDBall, 1: dJointTypeBall, 2: dJointTypeSlider (lo = hi = 0 stop)
};

/// The joints a soft row can be typed into, in the order of the "joint" setting's choices.
enum class OdeJoint { dball = 0, ball = 1, slider = 2 };

/// The model's ceiling on ERP: above it c + h k < 1e-6 h k, the row is all CFM and no spring (the
/// motion is a free drift no fit can read), so such a spring is reported, not exported.
inline constexpr double kOdeMaxErp = 1e6;

/// The lightest damping ratio `exact` aims at: ODE's step removes the fraction G = 1 - det of the
/// velocity every step, so zero damping needs G = 0, i.e. CFM = infinity; asked below this, exact aims
/// here (a tenth of the exact-damping tolerance).
inline constexpr double kOdeDampingFloor = 0.1 * kExactDampingTolerance;

/// The fraction of the row's exact impulse the stepper applies in one step: 1 for dWorldStep (the direct
/// LCP solve is exact); 1 - (1 - w)^N for dWorldQuickStep's N SOR sweeps from lambda = 0 (quickstep.cpp:
/// no WARM_STARTING, each sweep adds w (lambda* - lambda) on a row that no other row couples to).
double ode_impulse_fraction(const SettingValues& values);

/// ODE's step of one soft row on effective mass m over h for the ERP and CFM typed into the joint, with
/// impulse fraction rho: the state (x, v) after one world step. Exposed for tests.
Eigen::Matrix2d ode_step_map(double m, double erp, double cfm, double h, double rho);

}  // namespace softtune::engines

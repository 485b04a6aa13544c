#pragma once
// MuJoCo's soft constraints (solref, solimp) on one 1-D equality, modelled for 2.2.2 (Debian's
// libmujoco-dev) and checked against 3.x. Model in core/src/engines/mujoco.cpp; the real engine runs it in
// tests/engines/mujoco.

#include "softtune/engines/engine_model.h"

namespace softtune::engines {

extern const EngineModel kMujocoModel;

/// mjtIntegrator, in MuJoCo's own order (mjINT_EULER, mjINT_RK4, mjINT_IMPLICIT, mjINT_IMPLICITFAST; the
/// last is MuJoCo 3 only).
enum class MujocoIntegrator { euler = 0, rk4 = 1, implicit = 2, implicitfast = 3 };

/// Index of each setting in kMujocoModel.settings.
enum MujocoSetting : int {
  kMujocoIntegrator = 0,
  kMujocoSolimp0 = 1,  ///< d0, impedance at zero violation
  kMujocoSolimp1,      ///< d_width, impedance at and beyond `width`; K and B are normalised by it
  kMujocoSolimp2,      ///< width
  kMujocoSolimp3,      ///< midpoint
  kMujocoSolimp4,      ///< power
  kMujocoRefsafe,      ///< 0 enable (MuJoCo's default), 1 disable (mjDSBL_REFSAFE)
  kMujocoDiagRatio,    ///< rho = J M^-1 J' / efc_diagApprox of the row (1: joint or tendon equality)
  kMujocoSettingCount,
};

/// mj_defaultSolRefImp: what MuJoCo puts in place of a mixed-sign solref.
inline constexpr double kMujocoDefaultTimeconst = 0.02, kMujocoDefaultDampratio = 1.0;
/// mjMINIMP, mjMAXIMP: getsolparam clamps solimp[0], [1], [3] into this range.
inline constexpr double kMujocoMinImp = 0.0001, kMujocoMaxImp = 0.9999;
/// mjMINVAL: the floor of every denominator in mj_makeImpedance.
inline constexpr double kMujocoMinVal = 1e-15;

/// The reference acceleration MuJoCo's solver realises for one 1-D equality: the constraint's acceleration is
///   a = g a_ref + (1 - g) a0,  a_ref = -B v - K d r,  g = rho d / (1 - d + rho d),
/// rho = J M^-1 J' / efc_diagApprox (1 for a joint or tendon equality, where g = d), so with a0 = 0,
/// a = -beta v - kappa r with beta = g B, kappa = g d K (per unit effective mass).
struct MujocoGains {
  double beta = 0.0;   ///< 1/s
  double kappa = 0.0;  ///< 1/s^2
  double timeconst_used = 0.0;  ///< standard form: solref[0] after the 2h floor; 0 for the direct form
  bool replaced_by_default = false;  ///< the solref had mixed signs: MuJoCo used (0.02, 1)
  bool floored = false;              ///< the 2h floor raised solref[0]
};

/// getsolparam + mj_makeImpedance + mj_referenceConstraint for one row: solref as typed, the impedance
/// `imp` (getimpedance's value; solimp[0] = solimp[1] = imp when flat), d_width = solimp[1], the
/// timestep h, refsafe on or off, and rho = J M^-1 J' / efc_diagApprox.
MujocoGains mujoco_gains(double solref0, double solref1, double imp, double d_width, double h, bool refsafe,
                         double rho = 1.0);

/// One mj_step of the state (r, v) under a = -beta v - kappa r: Euler, implicit and implicitfast are
/// semi-implicit Euler (v1 = v0 + h a(r0, v0), r1 = r0 + h v1; the constraint force never enters the
/// implicit velocity derivative), RK4 is the classic four-stage Runge-Kutta (mj_RungeKutta).
Eigen::Matrix2d mujoco_step_map(MujocoIntegrator integrator, double beta, double kappa, double h);

}  // namespace softtune::engines

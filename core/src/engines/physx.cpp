// PhysX 5 (NVIDIA-Omniverse/PhysX, physx/version.txt 5.6.1), read but not run (no Debian or npm package):
//   include/extensions/PxD6Joint.h        PxD6JointDrive(stiffness, damping, forceLimit, isAcceleration);
//                                         isValid(): stiffness, damping, forceLimit finite and >= 0
//   physxextensions/src/ExtD6Joint.cpp    D6Joint::setDrive: PX_CHECK_AND_RETURN(d.isValid()) (checked builds
//                                         drop an invalid drive; release builds compile the check out);
//                                         d6JointSolverPrep: ch.linear(axis, -velocity, posErr, drive) per axis
//   physxextensions/src/ExtConstraintHelper.h  addDrive: Px1DConstraintFlag::eSPRING (| eACCELERATION_SPRING),
//                                         mods.spring.stiffness/damping, impulse limits +-forceLimit
//   lowleveldynamics/shared/DyCpuGpu1dConstraint.h
//     compute1dConstraintSolverConstantsPGS: a = dt (dt k + d), b = dt (d vT - k C);
//       force: x = 1 / (1 + a r), constant = x b, velMultiplier = -x a, impulseMultiplier = 1 - x
//       acceleration: x = 1 / (1 + a), constant = x b / r, velMultiplier = -x a / r, impulseMultiplier = 1 - x
//       then constant += initJointSpeed velMultiplier (PGS solver bodies carry velocity deltas)
//     compute1dConstraintSolverConstantsTGS: the same with dt -> stepDt = dt / positionIterations and the
//       error term biasScale = -x k stepDt (/ r) applied to the current error C0 + motion
//   lowleveldynamics/src/DyConstraintSetup.cpp  setupSolverConstraint: r = J M^-1 J^T (unitResponse),
//                                         initJointSpeed = J v
//   lowleveldynamics/src/DySolverConstraints.cpp  solve1D: f' = iMul f + vMul (J dv) + constant, then
//                                         dv += M^-1 J^T (f' - f); conclude1D: constant = unbiasedConstant (equal
//                                         for springs)
//   lowleveldynamics/src/DyTGSContactPrep.cpp  solve1DStep: f' = f + vMul (J v) + bias + targetVel, bias =
//                                         biasScale (C0 + motion); conclude1DStep: a spring row gets
//                                         velMultiplier = biasScale = 0 ("zero impulse during velocity iterations")
//   lowleveldynamics/src/DyTGSDynamics.cpp  iterativeSolveIsland: per position iteration solve, then
//                                         integrateBodies(stepDt); stepDt = dt / posIters (line "mStepDt = dt /")
//   lowleveldynamics/src/DyBodyCoreIntegrator.h  integrateCore: p += (v + dv) dt after the solve (PGS)
//   include/PxSceneDesc.h                 solverType default PxSolverType::ePGS
//   include/PxRigidDynamic.h              setSolverIterationCounts: default 4 position, 1 velocity; ranges
//                                         [1, 255] and [0, 255]
//
// One row, r = 1/m (m the effective mass), C the row's error x, v its rate:
//   PGS: the first pass gives f = -(a v + dt k x) / (1 + a r) (force drive), and every later pass, position or
//        velocity, returns the same f (f' - f = (1 - x(1 + a r)) (f - f*) = 0), so
//        v1 = v + r f = (m v - dt k x) / (m + dt d + dt^2 k), x1 = x + dt v1: implicit Euler on (m, k, d).
//   TGS: each of the N position iterations is that step at dt / N on the current error, followed by the
//        position integration; velocity iterations add nothing: N substeps of implicit Euler.
//   An acceleration drive is the same with r replaced by 1: implicit Euler on (1, k, d), whatever the mass.
// Not modelled: float rounding (PhysX computes in float), a body's sleep (a decaying drive falls asleep under
// PxRigidDynamic's sleepThreshold unless woken or the threshold is 0) and angular damping (default 0.05 1/s,
// which slows a rotating body's turn: set it to 0 for the rotating case).
#include "softtune/engines/physx.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "softtune/designer.h"
#include "softtune/exact_softness.h"

namespace softtune::engines {
namespace {

constexpr std::array<std::string_view, 2> kSolverChoices = {"ePGS", "eTGS"};
constexpr std::array<std::string_view, 2> kDriveChoices = {"force", "acceleration"};
constexpr std::array<SettingSpec, 4> kSettings = {{
    {"solverType", 0, 0, 1, true, kSolverChoices, "",
     "PxSceneDesc::solverType; TGS substeps the drive by the position iterations"},
    {"positionIterations", 4, 1, 255, true, {}, "",
     "PxRigidDynamic::setSolverIterationCounts minPositionIters (TGS: substeps of the drive)"},
    {"velocityIterations", 1, 0, 255, true, {}, "",
     "minVelocityIters; a drive row adds no impulse in them (TGS) or stays converged (PGS)"},
    {"driveType", 0, 0, 1, true, kDriveChoices, "",
     "PxD6JointDrive isAcceleration: the acceleration drive scales by the row's mass (stiffness per kg)"},
}};

bool acceleration_drive(const SettingValues& values) {
  return values.size() > kPhysxDriveType && values[kPhysxDriveType] != 0.0;
}

Parameters parameters_of(bool acceleration, double k, double d) {
  if (acceleration) {
    return {{"PxD6JointDrive::stiffness", k, "1/s^2"},
            {"PxD6JointDrive::damping", d, "1/s"},
            {"PxD6JointDrive::isAcceleration", 0.0, "", "true"}};
  }
  return {{"PxD6JointDrive::stiffness", k, "N/m"},
          {"PxD6JointDrive::damping", d, "N s/m"},
          {"PxD6JointDrive::isAcceleration", 0.0, "", "false"}};
}

// What PhysX does with the drive typed; empty for a drive the model does not export: one that
// PxD6JointDrive::isValid rejects (negative or beyond float), or no spring at all (stiffness 0).
std::optional<Prediction> predict_drive(double m, double k, double d, double dt, int substeps) {
  if (!(k > 0.0) || !(d >= 0.0) || !(k <= kPhysxFloatMax) || !(d <= kPhysxFloatMax)) return std::nullopt;
  return predict_from_step_map(physx_step_map(m, k, d, dt, substeps), dt);
}

bool meets(const Prediction& p, const Target& t) { return p.stable && meets_response(p, t.omega, t.damping_ratio); }

// The undamped drive (d = 0) whose implicit-Euler substep has natural frequency omega: its poles are
// z = (1 +- i q) / (1 + q^2), q = h sqrt(k / m), so s h = -ln(1 + q^2) / 2 +- i atan(q) and
// |s| h = g(q) = sqrt((ln(1 + q^2) / 2)^2 + atan(q)^2); Newton on g(q) = omega h (g increases, g(q) ~ q).
// Returns the stiffness k = m q^2 / h^2.
double undamped_stiffness_for(double m, double omega, double h) {
  const double target = omega * h;
  double q = target;
  for (int i = 0; i < 20; ++i) {
    const double half_log = 0.5 * std::log1p(q * q), angle = std::atan(q);
    const double g = std::hypot(half_log, angle);
    const double slope = (half_log * q + angle) / ((1.0 + q * q) * g);
    const double step = (g - target) / slope;
    q = std::max(q - step, 0.5 * q);
    if (std::abs(step) <= 1e-14 * q) break;
  }
  return m * q * q / (h * h);
}

EngineReport report(const Target& t, const SettingValues& values) {
  EngineReport out;
  out.settings = describe_settings(kPhysxModel, values);
  const bool acceleration = acceleration_drive(values);
  const int n = physx_substeps(values);
  // An acceleration drive acts on unit mass: type k / m and d / m.
  const double m = acceleration ? 1.0 : t.effective_mass, per = acceleration ? t.effective_mass : 1.0;
  const double h = t.dt, k = t.spring.stiffness / per, d = t.spring.damping / per;

  if (const std::optional<Prediction> p = predict_drive(m, k, d, h, n)) {
    out.parameters = parameters_of(acceleration, k, d);
    out.predicted = *p;
    if (!p->stable) out.warnings.push_back({WarningCode::engine_unstable, p->spectral_radius, 1.0, kPhysxModel.name});
  } else {
    out.predicted = {std::nullopt, std::nullopt, 1.0, true};
    out.warnings.push_back({WarningCode::engine_refuses, d, 0.0, kPhysxModel.name,
                            "PxD6JointDrive::isValid needs stiffness and damping finite and >= 0: a checked "
                            "build drops this drive, a release build takes a negative damping it can divide "
                            "by zero on"});
  }

  if (!(t.omega > 0.0)) return out;
  // Exact: the substep is implicit Euler at dt / n, so softtune's exact spring at dt / n puts the substep's
  // poles at exp(s dt / n), and the frame's at exp(s dt) (exact_softness.h, a closed form).
  const double h_sub = h / n;
  const ExactSpring closed = exact_spring(m, t.omega, t.damping_ratio, h_sub);
  if (closed.finite && !closed.clamped_to_nyquist && closed.spring.damping >= 0.0) {
    if (const std::optional<Prediction> p = predict_drive(m, closed.spring.stiffness, closed.spring.damping, h, n);
        p && meets(*p, t)) {
      out.exact = parameters_of(acceleration, closed.spring.stiffness, closed.spring.damping);
      out.exact_predicted = *p;
      return out;
    }
  }
  // Lighter damping than the substep's implicit Euler shows at d = 0 needs d < 0, which PhysX refuses: the
  // nearest is the undamped drive of the asked frequency (exact when within the damping tolerance).
  const char* why = "the asked frequency is above the step's Nyquist limit, or its poles overflow";
  if (closed.finite && !closed.clamped_to_nyquist) {
    const double k0 = undamped_stiffness_for(m, t.omega, h_sub);
    if (const std::optional<Prediction> p = predict_drive(m, k0, 0.0, h, n); p && p->frequency_hz && p->damping_ratio) {
      if (meets(*p, t)) {
        out.exact = parameters_of(acceleration, k0, 0.0);
        out.exact_predicted = *p;
        return out;
      }
      out.warnings.push_back({WarningCode::engine_inexact, *p->frequency_hz / frequency_from_angular(t.omega) - 1.0,
                              *p->damping_ratio - t.damping_ratio, kPhysxModel.name,
                              "implicit Euler at dt / substeps damps even an undamped drive, and PhysX refuses "
                              "negative damping: the nearest is damping 0 (TGS with more position iterations "
                              "damps less)"});
      return out;
    }
  }
  out.warnings.push_back({WarningCode::engine_inexact, 0.0, 0.0, kPhysxModel.name, why});
  return out;
}

}  // namespace

int physx_substeps(const SettingValues& values) {
  if (values.size() <= kPhysxPositionIterations || values[kPhysxSolverType] == 0.0) return 1;
  return std::max(1, static_cast<int>(values[kPhysxPositionIterations]));
}

// One substep at h = dt / n (compute1dConstraintSolverConstantsTGS with stepDt; PGS: n = 1, dt):
//   a = h (h k + d), x = 1 / (1 + a / m)
//   f = -x (a v + h k C)          (first pass; later passes leave it)
//   v1 = v + f / m = (m v - h k C) / (m + h d + h^2 k),  C1 = C + h v1
// and the step is that substep n times (powers of one matrix commute, so the order of the product is moot).
Eigen::Matrix2d physx_step_map(double m, double k, double d, double dt, int substeps) {
  const double h = dt / substeps;
  const double denominator = m + h * d + h * h * k;
  Eigen::Matrix2d sub;
  sub(1, 0) = -h * k / denominator;
  sub(1, 1) = m / denominator;
  sub(0, 0) = 1.0 + h * sub(1, 0);
  sub(0, 1) = h * sub(1, 1);
  // sub^n by squaring (n up to 255: at most 16 products).
  Eigen::Matrix2d out = Eigen::Matrix2d::Identity();
  for (int n = substeps; n > 0; n >>= 1) {
    if (n & 1) out = sub * out;
    sub = sub * sub;
  }
  return out;
}

const EngineModel kPhysxModel = {
    "physx",
    "PhysX 5.6.1 (source read, not run): ExtD6Joint.cpp, ExtConstraintHelper.h addDrive, DyCpuGpu1dConstraint.h, "
    "DySolverConstraints.cpp solve1D, DyTGSContactPrep.cpp solve1DStep, DyTGSDynamics.cpp iterativeSolveIsland",
    kSettings,
    report,
};

}  // namespace softtune::engines

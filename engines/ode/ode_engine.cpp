#include "ode_engine.h"

#include <ode/ode.h>

#include <cmath>
#include <mutex>

#include "ode_global.h"
#include "softtune/engines/ode.h"

namespace softtune::engines {
namespace {

constexpr double kDBallLength = 1.0;  // m, from the world anchor to the body's anchor at rest

double setting(const SettingValues& values, int index) {
  const auto i = static_cast<std::size_t>(index);
  return i < values.size() ? values[i] : kOdeModel.settings[i].default_value;
}

RunTrajectory run_ode(const EngineRun& run) {
  const auto joint_kind = static_cast<OdeJoint>(static_cast<int>(setting(run.settings, kOdeJoint)));
  const bool plank = run.body == RunBody::rotating_plank;
  if (plank && joint_kind == OdeJoint::slider) return {};
  const bool slider = joint_kind == OdeJoint::slider;
  const std::optional<double> erp = parameter_value(run.parameters, slider ? "dParamStopERP" : "dParamERP");
  const std::optional<double> cfm = parameter_value(run.parameters, slider ? "dParamStopCFM" : "dParamCFM");
  if (!erp || !cfm) return {};

  // One ODE run at a time (ode_global.h: libode's global scratch); a run is milliseconds.
  const std::lock_guard lock(ode_global_mutex());
  init_ode_for_this_thread();
  dWorldID world = dWorldCreate();
  dWorldSetGravity(world, 0, 0, 0);
  dWorldSetQuickStepNumIterations(world, static_cast<int>(setting(run.settings, kOdeIterations)));
  dWorldSetQuickStepW(world, setting(run.settings, kOdeSorW));
  const bool quick = setting(run.settings, kOdeStepper) != 0.0;

  dBodyID body = dBodyCreate(world);
  dMass mass;
  if (plank) {
    const PlankGeometry g = rotating_plank(run.effective_mass);
    dMassSetParameters(&mass, g.mass, 0, 0, 0, g.inertia, g.inertia, g.inertia, 0, 0, 0);
  } else {
    dMassSetParameters(&mass, run.effective_mass, 0, 0, 0, run.effective_mass, run.effective_mass,
                       run.effective_mass, 0, 0, 0);
  }
  dBodySetMass(body, &mass);
  dBodySetPosition(body, 0, 0, 0);
  const double offset = plank ? rotating_plank(run.effective_mass).offset : 0.0;

  // The joint at rest, then the body moved by x0 along x.
  dJointID joint = nullptr;
  switch (joint_kind) {
    case OdeJoint::dball:
      joint = dJointCreateDBall(world, nullptr);
      dJointAttach(joint, body, nullptr);
      dJointSetDBallAnchor1(joint, 0, offset, 0);
      dJointSetDBallAnchor2(joint, -kDBallLength, offset, 0);
      dJointSetDBallParam(joint, dParamERP, *erp);
      dJointSetDBallParam(joint, dParamCFM, *cfm);
      break;
    case OdeJoint::ball:
      joint = dJointCreateBall(world, nullptr);
      dJointAttach(joint, body, nullptr);
      dJointSetBallAnchor(joint, 0, offset, 0);
      dJointSetBallParam(joint, dParamERP, *erp);
      dJointSetBallParam(joint, dParamCFM, *cfm);
      break;
    case OdeJoint::slider:
      joint = dJointCreateSlider(world, nullptr);
      dJointAttach(joint, body, nullptr);
      dJointSetSliderAxis(joint, 1, 0, 0);
      dJointSetSliderParam(joint, dParamLoStop, 0);
      dJointSetSliderParam(joint, dParamHiStop, 0);
      dJointSetSliderParam(joint, dParamStopERP, *erp);
      dJointSetSliderParam(joint, dParamStopCFM, *cfm);
      break;
  }
  dBodySetPosition(body, run.x0, 0, 0);

  auto stretch = [&] {
    if (slider) return static_cast<double>(dJointGetSliderPosition(joint));
    dVector3 anchor;
    dBodyGetRelPointPos(body, 0, offset, 0, anchor);
    if (joint_kind == OdeJoint::ball) return static_cast<double>(anchor[0]);
    const double dx = anchor[0] + kDBallLength, dy = anchor[1] - offset, dz = anchor[2];
    return std::sqrt(dx * dx + dy * dy + dz * dz) - kDBallLength;
  };

  RunTrajectory x;
  x.reserve(static_cast<std::size_t>(run.steps) + 1);
  x.push_back(stretch());
  for (int i = 0; i < run.steps; ++i) {
    if (quick) {
      dWorldQuickStep(world, run.dt);
    } else {
      dWorldStep(world, run.dt);
    }
    x.push_back(stretch());
  }
  dWorldDestroy(world);
  return x;
}

}  // namespace

const RealEngine kOdeEngine = {"ode", dODE_VERSION, run_ode};

}  // namespace softtune::engines

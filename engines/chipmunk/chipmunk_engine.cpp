#include "chipmunk_engine.h"

#include <chipmunk/chipmunk.h>

#include <cmath>

#include "softtune/engines/chipmunk.h"

namespace softtune::engines {
namespace {

constexpr double kRestLength = 1.0;  // m, from the static anchor to the body's anchor at rest

double setting(const SettingValues& values, int index) {
  const auto i = static_cast<std::size_t>(index);
  return i < values.size() ? values[i] : kChipmunkModel.settings[i].default_value;
}

#define STRINGIFY_VERSION(a, b, c) #a "." #b "." #c
#define CHIPMUNK_VERSION(a, b, c) STRINGIFY_VERSION(a, b, c)
constexpr const char* kVersion = CHIPMUNK_VERSION(CP_VERSION_MAJOR, CP_VERSION_MINOR, CP_VERSION_RELEASE);

RunTrajectory run_chipmunk(const EngineRun& run) {
  const std::optional<double> stiffness = parameter_value(run.parameters, "cpDampedSpringSetStiffness");
  const std::optional<double> damping = parameter_value(run.parameters, "cpDampedSpringSetDamping");
  if (!stiffness || !damping) return {};

  cpSpace* space = cpSpaceNew();
  cpSpaceSetGravity(space, cpv(0, 0));
  cpSpaceSetIterations(space, static_cast<int>(setting(run.settings, kChipmunkIterations)));
  cpSpaceSetDamping(space, setting(run.settings, kChipmunkDamping));

  const bool plank = run.body == RunBody::rotating_plank;
  const PlankGeometry g = rotating_plank(run.effective_mass);
  cpBody* body = plank ? cpBodyNew(g.mass, g.inertia) : cpBodyNew(run.effective_mass, INFINITY);
  cpSpaceAddBody(space, body);
  const double offset = plank ? g.offset : 0.0;
  cpBodySetPosition(body, cpv(0, 0));
  cpConstraint* spring = cpDampedSpringNew(cpSpaceGetStaticBody(space), body, cpv(-kRestLength, offset),
                                           cpv(0, offset), kRestLength, *stiffness, *damping);
  cpSpaceAddConstraint(space, spring);
  cpBodySetPosition(body, cpv(run.x0, 0));

  auto stretch = [&] {
    const cpVect anchor = cpBodyLocalToWorld(body, cpv(0, offset));
    return cpvlength(cpvsub(anchor, cpv(-kRestLength, offset))) - kRestLength;
  };
  RunTrajectory x;
  x.reserve(static_cast<std::size_t>(run.steps) + 1);
  x.push_back(stretch());
  for (int i = 0; i < run.steps; ++i) {
    cpSpaceStep(space, run.dt);
    x.push_back(stretch());
  }
  cpSpaceRemoveConstraint(space, spring);
  cpConstraintFree(spring);
  cpSpaceRemoveBody(space, body);
  cpBodyFree(body);
  cpSpaceFree(space);
  return x;
}

}  // namespace

const RealEngine kChipmunkEngine = {"chipmunk", kVersion, run_chipmunk};

}  // namespace softtune::engines

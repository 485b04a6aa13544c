// The real engines linked in process, in the order answers list them. Each engine room adds one line.
#include <array>

#include "box2d_v2_4_run.h"
#include "bullet_engine.h"
#include "chipmunk_engine.h"
#include "mujoco_engine.h"
#include "ode_engine.h"
#include "softtune/engines/verify.h"

namespace softtune::engines {

std::span<const RealEngine* const> real_engines() {
  static constexpr std::array kEngines = {
      &kBox2DV24Engine,
      &kOdeEngine,
      &kBulletEngine,
      &kMujocoEngine,
      &kChipmunkEngine,
  };
  return kEngines;
}

}  // namespace softtune::engines

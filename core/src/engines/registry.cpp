// The modelled engines, in the order answers list them. Each engine adds its model here and nowhere else.
#include <array>

#include "softtune/engines/box2d_v2_4.h"
#include "softtune/engines/bullet.h"
#include "softtune/engines/mujoco.h"
#include "softtune/engines/box2d_v3.h"
#include "softtune/engines/engine_model.h"
#include "softtune/engines/ode.h"
#include "softtune/engines/physx.h"
#include "softtune/engines/jolt.h"
#include "softtune/engines/rapier.h"
#include "softtune/engines/chipmunk.h"
#include "softtune/engines/godot_2d.h"
#include "softtune/engines/matter_js.h"
#include "softtune/engines/planck_js.h"
#include "softtune/engines/cannon_es.h"

namespace softtune::engines {

std::span<const EngineModel* const> engine_models() {
  static constexpr std::array kModels = {
      &kBox2DV24Model, &kBox2DV3Model, &kJoltModel, &kMujocoModel,
      &kOdeModel,      &kBulletModel,  &kPhysxModel, &kRapierModel,
      &kChipmunkModel, &kGodot2DModel,
      &kMatterJsModel, &kPlanckJsModel, &kCannonEsModel,
  };
  return kModels;
}

}  // namespace softtune::engines

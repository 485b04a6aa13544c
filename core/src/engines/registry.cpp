// The modelled engines, in the order answers list them. Each engine adds its model here and nowhere else.
#include <array>

#include "softtune/engines/box2d_v2_4.h"
#include "softtune/engines/box2d_v3.h"
#include "softtune/engines/engine_model.h"

namespace softtune::engines {

std::span<const EngineModel* const> engine_models() {
  static constexpr std::array kModels = {
      &kBox2DV24Model,
      &kBox2DV3Model,
  };
  return kModels;
}

}  // namespace softtune::engines

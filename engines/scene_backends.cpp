// The scene backends linked into this build, in the order answers list them. Each engine room adds one line
// (its engines/<engine>/<engine>_scene.h and its softtune_scene_<engine> library in engines/CMakeLists.txt).
#include "softtune/engines/scene_backends.h"

#include <array>

#include "bullet_scene.h"
#include "jolt_scene.h"
#include "mujoco_scene.h"
#include "ode_scene.h"
#include "rapier_scene.h"
#include "softtune/scene/box2d_backend.h"

namespace softtune::engines {

std::span<const scene::SceneBackend* const> scene_backends() {
  static constexpr std::array kBackends = {
      &scene::kBox2DV24SceneBackend,
      &scene::kBulletSceneBackend,
      &scene::kOdeSceneBackend,
      &kMujocoSceneBackend,
      &kJoltSceneBackend,
      &kRapierSceneBackend,
  };
  return kBackends;
}

const scene::SceneBackend* find_scene_backend(std::string_view name) {
  for (const scene::SceneBackend* b : scene_backends()) {
    if (b->name == name) return b;
  }
  return nullptr;
}

}  // namespace softtune::engines

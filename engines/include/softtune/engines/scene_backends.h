#pragma once
// The scene backends of this build (scene/scene_world.h), in the order answers and the page list them:
// Box2D 2.4 first (the default engine of every scene contract), then each engine room's backend, one line each
// in engines/scene_backends.cpp.

#include <span>
#include <string_view>

#include "softtune/scene/scene_world.h"

namespace softtune::engines {

/// Every registered scene backend; names are unique.
std::span<const scene::SceneBackend* const> scene_backends();

/// The backend called `name` (SceneBackend::name, e.g. "box2d_v2_4"), or null.
const scene::SceneBackend* find_scene_backend(std::string_view name);

}  // namespace softtune::engines

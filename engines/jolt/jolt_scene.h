#pragma once
// Scenes in the real Jolt Physics (npm jolt-physics 1.1.0, WebAssembly) through the node worker:
// jolt_scene.mjs builds and steps them in the plane (EAllowedDOFs::Plane2D; docs/scene-backends.md).

#include "softtune/scene/scene_world.h"

extern const softtune::scene::SceneBackend kJoltSceneBackend;

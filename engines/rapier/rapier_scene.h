#pragma once
// Scenes in the real Rapier 2-D (npm @dimforge/rapier2d-compat 0.21.0, WebAssembly) through the node worker:
// rapier_scene.mjs builds and steps them (what maps to what: its header; docs/scene-backends.md).

#include "softtune/scene/scene_world.h"

extern const softtune::scene::SceneBackend kRapierSceneBackend;

#pragma once
// Box2D 2.4.1 as a scene backend (scene_world.h): the Box2DScene world behind the SceneWorld contract, its
// joints' springs under the joint defs' own names ("b2WheelJointDef::stiffness"), the world's iterations as
// its settings. The default engine of every scene contract.

#include "softtune/scene/scene_world.h"

namespace softtune::scene {

extern const SceneBackend kBox2DV24SceneBackend;

}  // namespace softtune::scene

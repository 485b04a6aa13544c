#pragma once
// Engine-neutral geometry of a scene: each body's mass data from its shape as Box2D 2.4 computes it (so every
// scene backend gives its engine the same masses and inertias), and the world outline of a body at a pose.

#include <Eigen/Core>
#include <vector>

#include "softtune/scene/scene.h"

namespace softtune::scene {

/// A body's mass data in its own frame (origin: the shape's centre, the body position).
struct MassData {
  double mass = 0.0;                     ///< kg; 0 for a static body
  double inertia = 0.0;                  ///< kg m^2 about the centre of mass; 0 when static or fixed_rotation
  Eigen::Vector2d local_centre{0, 0};    ///< m, centre of mass in the body frame
};

/// The mass data Box2D 2.4.1 gives the body's one fixture (b2PolygonShape::ComputeMass, b2CircleShape::
/// ComputeMass in src/collision/b2_polygon_shape.cpp and b2_circle_shape.cpp), scaled to `mass` when the body
/// gives one, as box2d_scene.cpp does with b2Body::SetMassData.
MassData body_mass(const BodySettings& body);

/// The shape's outline in the body frame: a box's or polygon's vertices counter-clockwise (empty for a circle).
std::vector<Eigen::Vector2d> local_outline(const ShapeSettings& shape);

}  // namespace softtune::scene

// Engine-neutral mass data (scene_geometry.cpp) against Box2D 2.4.1's own, for every shape kind: every scene
// backend gives its engine these masses, so they must be the ones the Box2D scene runs with.
#include "softtune/scene/scene_geometry.h"

#include <gtest/gtest.h>

#include "softtune/scene/box2d_scene.h"

namespace softtune::scene {
namespace {

BodySettings shaped(ShapeSettings shape, std::optional<double> mass, double density = 1.0) {
  BodySettings b;
  b.id = "b";
  b.shape = std::move(shape);
  b.mass = mass;
  b.density = density;
  b.position = {3.0, -2.0};
  b.angle = 0.7;
  return b;
}

void expect_box2d_mass(const BodySettings& body) {
  Scene s;
  s.bodies.push_back(body);
  Box2DScene world(s, MassModel::effective);
  const b2Body* b = world.bodies()[0];
  const MassData m = body_mass(body);
  EXPECT_NEAR(m.mass, b->GetMass(), 1e-5 * b->GetMass());
  const b2Vec2 lc = b->GetLocalCenter();
  EXPECT_NEAR(m.local_centre.x(), lc.x, 1e-5);
  EXPECT_NEAR(m.local_centre.y(), lc.y, 1e-5);
  const double inertia = b->GetInertia() - b->GetMass() * b2Dot(lc, lc);
  EXPECT_NEAR(m.inertia, inertia, 1e-4 * inertia);
}

TEST(SceneGeometry, MassDataIsBox2DsForEveryShape) {
  ShapeSettings box;
  box.width = 3.0;
  box.height = 0.5;
  expect_box2d_mass(shaped(box, 120.0));
  expect_box2d_mass(shaped(box, std::nullopt, 2.5));
  ShapeSettings circle;
  circle.kind = ShapeKind::circle;
  circle.radius = 0.4;
  expect_box2d_mass(shaped(circle, 15.0));
  ShapeSettings triangle;
  triangle.kind = ShapeKind::polygon;
  triangle.vertices = {{0, 0}, {2, 0}, {0.5, 1.5}};  // centroid off the origin
  expect_box2d_mass(shaped(triangle, 4.0));
  expect_box2d_mass(shaped(triangle, std::nullopt, 0.8));
}

TEST(SceneGeometry, StaticAndFixedRotationBodies) {
  ShapeSettings box;
  BodySettings ground = shaped(box, std::nullopt);
  ground.is_static = true;
  EXPECT_EQ(body_mass(ground).mass, 0.0);
  BodySettings slider = shaped(box, 2.0);
  slider.fixed_rotation = true;
  EXPECT_EQ(body_mass(slider).inertia, 0.0);
  EXPECT_NEAR(body_mass(slider).mass, 2.0, 1e-12);
}

}  // namespace
}  // namespace softtune::scene

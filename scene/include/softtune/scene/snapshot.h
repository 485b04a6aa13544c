#pragma once
// One recorded frame of a scene, for a renderer or a plot: plain world-space geometry, nothing to draw with.

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

namespace softtune::scene {

struct BodySnapshot {
  std::string id;
  bool is_static = false;
  bool probed = false;                         ///< a probe measures this body
  bool is_circle = false;
  std::vector<Eigen::Vector2d> vertices;       ///< m, world polygon (boxes and polygons)
  Eigen::Vector2d center{0, 0};                ///< m, world: circle centre, or the body origin
  double radius = 0.0;                         ///< m, circles
  double angle = 0.0;                          ///< rad
  Eigen::Vector2d mass_centre{0, 0};           ///< m, world centre of mass (b2Body::GetWorldCenter)
};

/// One point of a touching contact, as Box2D's testbed draws it (testbed/test.cpp, Test::PreSolve).
struct ContactSnapshot {
  Eigen::Vector2d point{0, 0};                 ///< m, world (b2WorldManifold::points)
  Eigen::Vector2d normal{0, 1};                ///< unit, from body A to body B (b2WorldManifold::normal)
};

struct JointSnapshot {
  std::string id;
  std::string kind;                            ///< joint_kind_name()
  Eigen::Vector2d anchor_a{0, 0};              ///< m, world (the mouse target for a mouse joint)
  Eigen::Vector2d anchor_b{0, 0};              ///< m, world
  std::optional<double> rest_length;           ///< m, distance joints
  double current_length = 0.0;                 ///< m, |anchor_b - anchor_a|
};

struct Snapshot {
  int frame = 0;
  double time_s = 0.0;                         ///< s
  std::vector<BodySnapshot> bodies;
  std::vector<JointSnapshot> joints;
  std::vector<ContactSnapshot> contacts;       ///< every point of every touching contact
};

}  // namespace softtune::scene

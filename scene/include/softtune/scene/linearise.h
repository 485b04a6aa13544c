#pragma once
// The linear model of a Box2D scene about its rest state (core modes.h): the scene is built and stepped in
// Box2D until it settles (every dynamic body slower than kRestSpeed for kRestFrames frames), until the first
// wheel motor switches on, or until `at_s`; then its bodies' mass data, its joints' rows at their current
// anchors and axes, and its touching contacts become a modes::LinearModel:
//   distance  tuned: a soft row along the anchors (k, c as tuned, preload -k (|d| - L)); rigid: a rigid row
//   wheel     a soft row along the axis turning with body A (preload -k translation) and a rigid row across it
//             (box2d v2.4.1 src/dynamics/b2_wheel_joint.cpp: the spring row and the "point to line" row)
//   weld      two rigid rows (x, y) at the anchor and the angular row, soft when tuned (b2_weld_joint.cpp)
//   mouse     two soft world rows (x, y) from the target (b2_mouse_joint.cpp solves the 2-D point)
//   revolute  two rigid rows (x, y) at the pin (b2_revolute_joint.cpp, the point constraint)
//   contact   per manifold point a rigid normal row (a circle's anchored at its centre, so it rolls) and, with
//             friction, a rigid tangent row at the contact point: a resting contact holds, it neither slides
//             nor lifts (b2_contact_solver.cpp, the normal and friction rows)
//   fixed_rotation bodies get a rigid angular row.
// The rigid rows' forces at rest come from the balance with gravity and the springs' preloads.

#include <optional>
#include <string>
#include <vector>

#include "softtune/diagnostics.h"
#include "softtune/modes.h"
#include "softtune/scene/joint_tuning.h"
#include "softtune/scene/scene.h"

namespace softtune::scene {

/// m/s (and rad/s times 1 m): a body slower than this counts as at rest.
inline constexpr double kRestSpeed = 2e-3;
/// Consecutive frames every body must stay at rest for the scene to count as settled.
inline constexpr int kRestFrames = 10;

struct LinearisedScene {
  modes::LinearModel model;
  std::vector<int> scene_body;            ///< model body -> index into scene.bodies
  std::vector<int> model_body;            ///< scene body -> model body, -1 for static bodies
  std::vector<JointTuning> joints;        ///< the k, c each joint was given (as the runner tunes them)
  double at_s = 0.0;                      ///< s, when the state was read
  bool settled = false;                   ///< the rest criterion held (else the state at at_s, still moving)
  int contact_points = 0;                 ///< touching manifold points turned into rows
  double balance_residual = 0.0;          ///< N, what the rigid rows could not balance (0 at a true rest)
  double h = 0.0;                         ///< s, the solver step 1 / (fps substeps)
};

struct LinearisationOptions {
  std::optional<double> at_s;             ///< s, read the state at this time instead of when it settles
};

/// A scene a linearisation can take: Box2D bodies, at most limits::kMaxModeBodies dynamic ones; `at_s` within
/// the run. The error names `field_prefix` + the field.
std::optional<FieldError> check_linearisable(const Scene& scene, std::optional<double> at_s, const std::string& at_field);

/// Linearises a scene that passed validate_scene() and has bodies; a joint tuning error is returned.
std::optional<FieldError> linearise_scene(const Scene& scene, MassModel mass_model, const LinearisationOptions& options,
                                          LinearisedScene& out);

/// The indices of the model rows that belong to scene joint `joint` and carry its spring.
std::vector<int> spring_rows(const LinearisedScene& s, int joint);

}  // namespace softtune::scene

#pragma once
// Effective mass of a 1-D constraint: m_eff = 1 / (J M^-1 J^T) (Catto GDC 2011, "3:2"), and the talk's
// mental experiment (Catto GDC 2011, "3:1"): apply equal and opposite unit impulses at the anchors, read
// the relative anchor velocity along the axis, m_eff = 1 / that velocity.

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <optional>

namespace softtune {

/// A rigid body in the plane. A static body has infinite mass and inertia.
struct Body2D {
  bool is_static = false;
  double mass = 1.0;                 ///< kg, > 0 for a dynamic body
  std::optional<double> inertia;     ///< kg m^2 about the centre of mass; absent = rotation locked
  Eigen::Vector2d position{0, 0};    ///< m, world position of the centre of mass
  double angle = 0.0;                ///< rad (does not change a 2-D effective mass; kept for scenes)
};

/// A rigid body in space. `inertia` is the body-frame tensor about the centre of mass.
struct Body3D {
  bool is_static = false;
  double mass = 1.0;                                   ///< kg
  std::optional<Eigen::Matrix3d> inertia;              ///< kg m^2, body frame; absent = rotation locked
  Eigen::Vector3d position{0, 0, 0};                   ///< m, world
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();  ///< body to world
};

enum class ConstraintType {
  linear,   ///< relative anchor velocity along `axis`
  angular,  ///< relative angular velocity about `axis` (3-D) or about z (2-D)
};

/// A 1-D constraint between two planar bodies. Anchors are world points; axis is a world direction.
struct Constraint2D {
  ConstraintType type = ConstraintType::linear;
  Body2D body_a, body_b;
  Eigen::Vector2d anchor_a{0, 0}, anchor_b{0, 0};  ///< m, world
  Eigen::Vector2d axis{1, 0};                      ///< unit direction, world
};

struct Constraint3D {
  ConstraintType type = ConstraintType::linear;
  Body3D body_a, body_b;
  Eigen::Vector3d anchor_a{0, 0, 0}, anchor_b{0, 0, 0};  ///< m, world
  Eigen::Vector3d axis{1, 0, 0};                         ///< unit direction, world
};

/// Inverse effective mass K = J M^-1 J^T, in 1/kg (linear) or 1/(kg m^2) (angular).
/// Linear 2-D: K = 1/mA + 1/mB + (rA x n)^2 / IA + (rB x n)^2 / IB, r = anchor - centre of mass.
/// Angular 2-D: K = 1/IA + 1/IB. Static bodies and locked rotations contribute 0.
double inverse_effective_mass(const Constraint2D& c);
/// Linear 3-D: K = 1/mA + 1/mB + (rA x n)^T IA^-1 (rA x n) + (rB x n)^T IB^-1 (rB x n),
/// I^-1 = R Ibody^-1 R^T. Angular 3-D: K = n^T (IA^-1 + IB^-1) n.
double inverse_effective_mass(const Constraint3D& c);

/// The talk's unit-impulse experiment, coded from velocities (no Jacobian): returns the relative
/// anchor velocity (or angular velocity) along the axis after +1 at B and -1 at A. Equals K.
double unit_impulse_response(const Constraint2D& c);
double unit_impulse_response(const Constraint3D& c);

/// What Box2D 2.4's b2LinearStiffness uses: mA mB / (mA + mB), or the dynamic body's mass when the
/// other is static (box2d 2.4.1 src/dynamics/b2_joint.cpp). Ignores rotation and anchors.
double box2d_reduced_mass(double mass_a, bool static_a, double mass_b, bool static_b);

}  // namespace softtune

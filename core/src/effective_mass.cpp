#include "softtune/effective_mass.h"
#include "softtune/effective_mass_terms.h"

namespace softtune {
namespace {

double inverse_mass(bool is_static, double mass) { return is_static ? 0.0 : 1.0 / mass; }

double inverse_inertia(const Body2D& b) {
  return (b.is_static || !b.inertia) ? 0.0 : 1.0 / *b.inertia;
}

// World inverse inertia R Ibody^-1 R^T; zero for static bodies and locked rotation.
Eigen::Matrix3d inverse_inertia(const Body3D& b) {
  if (b.is_static || !b.inertia) return Eigen::Matrix3d::Zero();
  const Eigen::Matrix3d r = b.orientation.normalized().toRotationMatrix();
  return r * b.inertia->inverse() * r.transpose();
}

double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return a.x() * b.y() - a.y() * b.x(); }

}  // namespace

InverseMassTerms inverse_effective_mass_terms(const Constraint2D& c) {
  const double ia = inverse_inertia(c.body_a), ib = inverse_inertia(c.body_b);
  InverseMassTerms t;
  if (c.type == ConstraintType::angular) {
    t.a_rotational = ia;
    t.b_rotational = ib;
    return t;
  }
  const double rna = cross(c.anchor_a - c.body_a.position, c.axis);
  const double rnb = cross(c.anchor_b - c.body_b.position, c.axis);
  t.a_translational = inverse_mass(c.body_a.is_static, c.body_a.mass);
  t.b_translational = inverse_mass(c.body_b.is_static, c.body_b.mass);
  t.a_rotational = ia * rna * rna;
  t.b_rotational = ib * rnb * rnb;
  return t;
}

double inverse_effective_mass(const Constraint2D& c) {
  const InverseMassTerms t = inverse_effective_mass_terms(c);
  return t.a_translational + t.b_translational + t.a_rotational + t.b_rotational;
}

double inverse_effective_mass(const Constraint3D& c) {
  const Eigen::Matrix3d ia = inverse_inertia(c.body_a), ib = inverse_inertia(c.body_b);
  if (c.type == ConstraintType::angular) return c.axis.dot((ia + ib) * c.axis);
  const Eigen::Vector3d rna = (c.anchor_a - c.body_a.position).cross(c.axis);
  const Eigen::Vector3d rnb = (c.anchor_b - c.body_b.position).cross(c.axis);
  return inverse_mass(c.body_a.is_static, c.body_a.mass) + inverse_mass(c.body_b.is_static, c.body_b.mass) +
         rna.dot(ia * rna) + rnb.dot(ib * rnb);
}

// The experiment: velocity changes of each body from the applied impulse, then the relative velocity of
// the anchor points v + w x r along the axis.
double unit_impulse_response(const Constraint2D& c) {
  struct Kick {
    Eigen::Vector2d v{0, 0};
    double w = 0.0;
  };
  auto kick = [](const Body2D& b, const Eigen::Vector2d& r, const Eigen::Vector2d& impulse, bool angular) {
    Kick k;
    if (b.is_static) return k;
    const double inv_i = b.inertia ? 1.0 / *b.inertia : 0.0;
    if (angular) {
      k.w = inv_i * impulse.x();  // an angular impulse (torque impulse) of that size about z
      return k;
    }
    k.v = impulse / b.mass;
    k.w = inv_i * (r.x() * impulse.y() - r.y() * impulse.x());
    return k;
  };
  auto anchor_velocity = [](const Kick& k, const Eigen::Vector2d& r) {
    return Eigen::Vector2d(k.v.x() - k.w * r.y(), k.v.y() + k.w * r.x());
  };
  const bool angular = c.type == ConstraintType::angular;
  const Eigen::Vector2d ra = c.anchor_a - c.body_a.position, rb = c.anchor_b - c.body_b.position;
  const Eigen::Vector2d unit = angular ? Eigen::Vector2d(1, 0) : c.axis;
  const Kick ka = kick(c.body_a, ra, -unit, angular), kb = kick(c.body_b, rb, unit, angular);
  if (angular) return kb.w - ka.w;
  return (anchor_velocity(kb, rb) - anchor_velocity(ka, ra)).dot(c.axis);
}

double unit_impulse_response(const Constraint3D& c) {
  struct Kick {
    Eigen::Vector3d v = Eigen::Vector3d::Zero();
    Eigen::Vector3d w = Eigen::Vector3d::Zero();
  };
  const bool angular = c.type == ConstraintType::angular;
  auto kick = [angular](const Body3D& b, const Eigen::Vector3d& r, const Eigen::Vector3d& impulse) {
    Kick k;
    if (b.is_static) return k;
    const Eigen::Matrix3d inv_i = inverse_inertia(b);
    if (angular) {
      k.w = inv_i * impulse;
      return k;
    }
    k.v = impulse / b.mass;
    k.w = inv_i * r.cross(impulse);
    return k;
  };
  const Eigen::Vector3d ra = c.anchor_a - c.body_a.position, rb = c.anchor_b - c.body_b.position;
  const Kick ka = kick(c.body_a, ra, -c.axis), kb = kick(c.body_b, rb, c.axis);
  if (angular) return (kb.w - ka.w).dot(c.axis);
  const Eigen::Vector3d va = ka.v + ka.w.cross(ra), vb = kb.v + kb.w.cross(rb);
  return (vb - va).dot(c.axis);
}

double box2d_reduced_mass(double mass_a, bool static_a, double mass_b, bool static_b) {
  if (static_a && static_b) return 0.0;
  if (static_a) return mass_b;
  if (static_b) return mass_a;
  return mass_a * mass_b / (mass_a + mass_b);
}

}  // namespace softtune

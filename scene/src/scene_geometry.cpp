#include "softtune/scene/scene_geometry.h"

#include <numbers>

namespace softtune::scene {

std::vector<Eigen::Vector2d> local_outline(const ShapeSettings& shape) {
  switch (shape.kind) {
    case ShapeKind::box: {
      const double w = shape.width / 2, h = shape.height / 2;
      return {{-w, -h}, {w, -h}, {w, h}, {-w, h}};
    }
    case ShapeKind::polygon: return shape.vertices;
    case ShapeKind::circle: break;
  }
  return {};
}

namespace {

// b2PolygonShape::ComputeMass: triangles fanned from a reference point inside the polygon (its first vertex),
// area, centroid and the second moment about the origin, then the inertia moved to the centroid.
MassData polygon_mass(const std::vector<Eigen::Vector2d>& v, double density) {
  const Eigen::Vector2d s = v.front();
  double area = 0.0, inertia = 0.0;
  Eigen::Vector2d centre{0, 0};
  constexpr double k_inv3 = 1.0 / 3.0;
  for (std::size_t i = 0; i < v.size(); ++i) {
    const Eigen::Vector2d e1 = v[i] - s, e2 = v[(i + 1) % v.size()] - s;
    const double d = e1.x() * e2.y() - e1.y() * e2.x();
    const double triangle_area = 0.5 * d;
    area += triangle_area;
    centre += triangle_area * k_inv3 * (e1 + e2);
    const double intx2 = e1.x() * e1.x() + e2.x() * e1.x() + e2.x() * e2.x();
    const double inty2 = e1.y() * e1.y() + e2.y() * e1.y() + e2.y() * e2.y();
    inertia += (0.25 * k_inv3 * d) * (intx2 + inty2);
  }
  MassData m;
  m.mass = density * area;
  centre /= area;
  m.local_centre = centre + s;
  // Inertia about the reference point, moved to the centroid (parallel axis theorem).
  m.inertia = density * inertia + m.mass * (m.local_centre.squaredNorm() - centre.squaredNorm());
  m.inertia -= m.mass * m.local_centre.squaredNorm();
  return m;
}

}  // namespace

MassData body_mass(const BodySettings& body) {
  if (body.is_static) return {};
  MassData m;
  if (body.shape.kind == ShapeKind::circle) {
    const double r = body.shape.radius;
    m.mass = body.density * std::numbers::pi * r * r;
    m.inertia = m.mass * 0.5 * r * r;
  } else {
    m = polygon_mass(local_outline(body.shape), body.density);
  }
  if (body.mass && m.mass > 0.0) {
    const double scale = *body.mass / m.mass;
    m.mass *= scale;
    m.inertia *= scale;
  }
  if (body.fixed_rotation) m.inertia = 0.0;
  return m;
}

}  // namespace softtune::scene

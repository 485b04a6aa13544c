#include "softtune/validation.h"

#include <Eigen/Eigenvalues>
#include <cmath>
#include <fmt/format.h>

namespace softtune {

std::string finite_range_rule(double lo, double hi, std::string_view unit) {
  return fmt::format("must be a finite number in [{:g}, {:g}]{}{}", lo, hi, unit.empty() ? "" : " ", unit);
}

namespace {

// A failed check: the field path and its rule.
std::optional<FieldError> check_range(double value, double lo, double hi, const std::string& field,
                                      const char* unit) {
  if (std::isfinite(value) && value >= lo && value <= hi) return std::nullopt;
  return FieldError{field, finite_range_rule(lo, hi, unit)};
}

std::optional<FieldError> check_vector(const double* v, int n, const std::string& field) {
  for (int i = 0; i < n; ++i) {
    if (!std::isfinite(v[i]) || std::abs(v[i]) > limits::kMaxCoordinate) {
      return FieldError{field, finite_range_rule(-limits::kMaxCoordinate, limits::kMaxCoordinate, "m") +
                                   " in every component"};
    }
  }
  return std::nullopt;
}

template <typename Body>
std::optional<FieldError> check_body_mass(const Body& b, const std::string& path) {
  if (b.is_static) return std::nullopt;
  return check_range(b.mass, limits::kMinMass, limits::kMaxMass, path + ".mass", "kg");
}

std::optional<FieldError> check_body(const Body2D& b, const std::string& path) {
  if (b.is_static) return std::nullopt;
  if (auto e = check_body_mass(b, path)) return e;
  if (b.inertia) {
    if (auto e = check_range(*b.inertia, limits::kMinInertia, limits::kMaxInertia, path + ".inertia", "kg m^2"))
      return e;
  }
  if (auto e = check_vector(b.position.data(), 2, path + ".position")) return e;
  if (!std::isfinite(b.angle)) return FieldError{path + ".angle", "must be a finite number (rad)"};
  return std::nullopt;
}

std::optional<FieldError> check_body(const Body3D& b, const std::string& path) {
  if (b.is_static) return std::nullopt;
  if (auto e = check_body_mass(b, path)) return e;
  if (b.inertia) {
    const Eigen::Matrix3d& i = *b.inertia;
    if (!i.allFinite()) return FieldError{path + ".inertia", "must hold finite numbers (kg m^2)"};
    if ((i - i.transpose()).cwiseAbs().maxCoeff() > 1e-9 * i.cwiseAbs().maxCoeff())
      return FieldError{path + ".inertia", "must be a symmetric 3x3 tensor"};
    const Eigen::Vector3d eig = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(i).eigenvalues();
    if (!(eig.minCoeff() >= limits::kMinInertia) || !(eig.maxCoeff() <= limits::kMaxInertia))
      return FieldError{path + ".inertia", "must be positive definite: each principal moment " +
                                               finite_range_rule(limits::kMinInertia, limits::kMaxInertia, "kg m^2")};
  }
  if (auto e = check_vector(b.position.data(), 3, path + ".position")) return e;
  const Eigen::Vector4d q = b.orientation.coeffs();
  if (!q.allFinite() || q.norm() < 1e-6)
    return FieldError{path + ".orientation", "must be a finite non-zero quaternion [w, x, y, z]"};
  return std::nullopt;
}

template <typename C>
std::optional<FieldError> check_constraint(const C& c) {
  constexpr int n = static_cast<int>(decltype(c.axis)::RowsAtCompileTime);
  if (c.body_a.is_static && c.body_b.is_static)
    return FieldError{"constraint.body_b", "at least one body must be dynamic (both are static)"};
  if (auto e = check_body(c.body_a, "constraint.body_a")) return e;
  if (auto e = check_body(c.body_b, "constraint.body_b")) return e;
  if (auto e = check_vector(c.anchor_a.data(), n, "constraint.anchor_a")) return e;
  if (auto e = check_vector(c.anchor_b.data(), n, "constraint.anchor_b")) return e;
  if (!c.axis.allFinite() || c.axis.norm() < limits::kMinAxisLength)
    return FieldError{"constraint.axis", "must be a finite non-zero vector"};
  if (!(inverse_effective_mass(c) > 0.0))
    return FieldError{"constraint", "the bodies give the constraint no mobility along the axis (J M^-1 J^T = "
                                    "0): give a dynamic body a mass, or an inertia for an angular constraint"};
  return std::nullopt;
}

}  // namespace

std::optional<FieldError> validate_tune_request(const TuneRequest& r) {
  if (auto e = check_range(r.fps, limits::kMinFps, limits::kMaxFps, "fps", "Hz")) return e;
  if (r.substeps < 1 || r.substeps > limits::kMaxSubsteps)
    return FieldError{"substeps", "must be an integer in [1, " + std::to_string(limits::kMaxSubsteps) + "]"};
  if (r.fps * r.substeps > limits::kMaxStepRate)
    return FieldError{"substeps", "fps * substeps must be at most 1e6 steps per second"};

  if (r.response_frames.has_value() == r.frequency_hz.has_value())
    return FieldError{"response_frames", "give exactly one of response_frames or frequency_hz"};
  if (r.response_frames) {
    if (auto e = check_range(*r.response_frames, limits::kMinFrames, limits::kMaxFrames, "response_frames",
                             "frames"))
      return e;
    if (auto e = check_range(r.basis_fps, limits::kMinFps, limits::kMaxFps, "basis_fps", "Hz")) return e;
  } else if (auto e = check_range(*r.frequency_hz, 0.0, limits::kMaxFrequencyHz, "frequency_hz", "Hz")) {
    return e;
  }

  if (r.oscillation.has_value() == r.damping_ratio.has_value())
    return FieldError{"oscillation", "give exactly one of oscillation or damping_ratio"};
  if (r.damping_ratio) {
    if (auto e = check_range(*r.damping_ratio, 0.0, limits::kMaxDampingRatio, "damping_ratio", "")) return e;
  }

  if (r.effective_mass.has_value() == r.constraint.has_value())
    return FieldError{"effective_mass", "give exactly one of effective_mass or constraint"};
  if (r.effective_mass) {
    return check_range(*r.effective_mass, limits::kMinMass, limits::kMaxMass, "effective_mass", "kg");
  }
  return std::visit([](const auto& c) { return check_constraint(c); }, *r.constraint);
}

}  // namespace softtune

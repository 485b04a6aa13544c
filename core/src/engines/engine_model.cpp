#include "softtune/engines/engine_model.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <numbers>

#include "softtune/designer.h"
#include "softtune/discrete_analysis.h"

namespace softtune::engines {

const SettingValues& default_settings_of(const EngineModel& model) {
  // Built once per model, so a tune with the defaults allocates none.
  static const std::vector<SettingValues> all = [] {
    std::vector<SettingValues> out;
    for (const EngineModel* m : engine_models()) out.push_back(default_settings(*m));
    return out;
  }();
  const auto models = engine_models();
  for (std::size_t i = 0; i < models.size(); ++i) {
    if (models[i] == &model) return all[i];
  }
  static const SettingValues none;
  return none;
}

SettingValues default_settings(const EngineModel& model) {
  SettingValues values;
  values.reserve(model.settings.size());
  for (const SettingSpec& spec : model.settings) values.push_back(spec.default_value);
  return values;
}

Parameters describe_settings(const EngineModel& model, const SettingValues& values) {
  Parameters out;
  out.reserve(model.settings.size());
  for (std::size_t i = 0; i < model.settings.size() && i < values.size(); ++i) {
    const SettingSpec& spec = model.settings[i];
    Parameter p{spec.name, values[i], spec.unit, {}};
    if (!spec.choices.empty()) {
      const auto index = static_cast<std::size_t>(values[i]);
      p.choice = index < spec.choices.size() ? spec.choices[index] : std::string_view{};
      p.value = 0.0;
    }
    out.push_back(std::move(p));
  }
  return out;
}

const EngineModel* find_engine_model(std::string_view name) {
  for (const EngineModel* model : engine_models()) {
    if (model->name == name) return model;
  }
  return nullptr;
}

std::optional<double> parameter_value(const Parameters& parameters, std::string_view name) {
  for (const Parameter& p : parameters) {
    if (p.name == name) return p.value;
  }
  return std::nullopt;
}

namespace {

Prediction prediction_of_poles(std::complex<double> z1, std::complex<double> z2, double spectral_radius,
                               double dt) {
  Prediction out;
  out.spectral_radius = spectral_radius;
  out.stable = classify_spectral_radius(spectral_radius) != Verdict::unstable;
  double frequency = 0.0, zeta = 0.0;
  if (achieved_from_poles(z1, z2, dt, frequency, zeta) && std::isfinite(frequency) && std::isfinite(zeta)) {
    out.frequency_hz = frequency;
    out.damping_ratio = zeta;
  }
  return out;
}

Prediction unstable_prediction() {
  Prediction out;
  out.spectral_radius = std::numeric_limits<double>::infinity();
  out.stable = false;
  return out;
}

}  // namespace

Prediction predict_from_step_map(const Eigen::Matrix2d& step_map, double dt) {
  if (!step_map.allFinite()) return unstable_prediction();
  std::complex<double> z1, z2;
  eigenvalues_2x2(step_map, z1, z2);
  // |z| squared: std::abs(complex) goes through hypot, a tenth of a model's whole report.
  const double r1 = std::norm(z1), r2 = std::norm(z2);
  if (r2 > r1) std::swap(z1, z2);
  if (z1.imag() < 0.0) std::swap(z1, z2);  // a conjugate pair: either order reads the same oscillation
  return prediction_of_poles(z1, z2, std::sqrt(std::max(r1, r2)), dt);
}

Prediction predict_from_step_map(const Eigen::MatrixXd& step_map, double dt) {
  if (step_map.rows() == 2 && step_map.cols() == 2) {
    return predict_from_step_map(Eigen::Matrix2d(step_map), dt);
  }
  if (step_map.rows() < 2 || step_map.rows() != step_map.cols() || !step_map.allFinite()) {
    return unstable_prediction();
  }
  Eigen::EigenSolver<Eigen::MatrixXd> solver(step_map, /*computeEigenvectors=*/false);
  Eigen::VectorXcd z = solver.eigenvalues();
  std::vector<std::complex<double>> poles(z.data(), z.data() + z.size());
  // Largest modulus first; of a conjugate pair the one with positive imaginary part first, so the pair
  // stays together and achieved_from_poles reads it as one oscillation.
  std::sort(poles.begin(), poles.end(), [](std::complex<double> a, std::complex<double> b) {
    const double ra = std::abs(a), rb = std::abs(b);
    if (std::abs(ra - rb) > 1e-12 * std::max(ra, rb)) return ra > rb;
    return a.imag() > b.imag();
  });
  return prediction_of_poles(poles[0], poles[1], std::abs(poles[0]), dt);
}

namespace {

struct Residual {
  double frequency = 0.0;  // ln(f / f_asked)
  double damping = 0.0;    // zeta - zeta_asked
  bool ok = false;
  Prediction prediction;
  double norm_scaled() const {
    return std::hypot(frequency / kExactFrequencyTolerance, damping / kExactDampingTolerance);
  }
};

}  // namespace

bool meets_response(const Prediction& p, double omega, double zeta, double scale) {
  return p.frequency_hz && p.damping_ratio &&
         std::abs(*p.frequency_hz / frequency_from_angular(omega) - 1.0) <= scale * kExactFrequencyTolerance &&
         std::abs(*p.damping_ratio - zeta) <= scale * kExactDampingTolerance;
}

bool within_nearest(const Prediction& p, double omega, double zeta) {
  return p.stable && p.frequency_hz && p.damping_ratio &&
         std::abs(*p.frequency_hz / frequency_from_angular(omega) - 1.0) <= kNearestFrequencyTolerance &&
         std::abs(*p.damping_ratio - zeta) <= kNearestDampingTolerance;
}

ResponseSolve solve_response(const std::function<std::optional<Prediction>(double p0, double p1)>& predict,
                             double omega, double zeta, double guess0, double guess1) {
  const double asked_hz = omega / (2.0 * std::numbers::pi);
  int evaluations = 0;
  auto residual = [&](double log_p0, double p1) {
    Residual r;
    ++evaluations;
    const double p0 = std::exp(log_p0);
    if (!std::isfinite(p0) || !std::isfinite(p1)) return r;
    const std::optional<Prediction> p = predict(p0, p1);
    if (!p || !p->stable || !p->frequency_hz || !p->damping_ratio || !(*p->frequency_hz > 0.0)) return r;
    r.frequency = std::log(*p->frequency_hz / asked_hz);
    r.damping = *p->damping_ratio - zeta;
    r.ok = std::isfinite(r.frequency) && std::isfinite(r.damping);
    r.prediction = *p;
    return r;
  };

  ResponseSolve out;
  if (!(omega > 0.0) || !(guess0 > 0.0) || !std::isfinite(guess1)) return out;
  double x0 = std::log(guess0), x1 = guess1;
  Residual best = residual(x0, x1);
  // A damping scale for finite differences and steps: the guess, else one relative to the stiffness.
  const double p1_scale = std::max(std::abs(guess1), 1e-6 * guess0 + 1e-300);
  if (best.ok) {
    // Levenberg-Marquardt on the residual scaled by its tolerances, so an unreachable damping ratio does
    // not stop the frequency from being met (plain Newton stalls on the singular direction).
    double lambda = 1e-3;
    for (int iteration = 0; iteration < 80 && evaluations < kMaxSolveEvaluations; ++iteration) {
      if (std::abs(best.frequency) < 0.1 * kExactFrequencyTolerance &&
          std::abs(best.damping) < 0.1 * kExactDampingTolerance) {
        break;
      }
      const double d0 = 1e-6, d1 = 1e-6 * std::max(std::abs(x1), p1_scale);
      const Residual r0 = residual(x0 + d0, x1), r1 = residual(x0, x1 + d1);
      if (!r0.ok || !r1.ok) break;
      const double wf = 1.0 / kExactFrequencyTolerance, wd = 1.0 / kExactDampingTolerance;
      const double rf = wf * best.frequency, rd = wd * best.damping;
      const double j00 = wf * (r0.frequency - best.frequency) / d0, j01 = wf * (r1.frequency - best.frequency) / d1;
      const double j10 = wd * (r0.damping - best.damping) / d0, j11 = wd * (r1.damping - best.damping) / d1;
      // Normal equations (J^T J + lambda diag(J^T J)) step = -J^T r.
      const double a00 = j00 * j00 + j10 * j10, a01 = j00 * j01 + j10 * j11, a11 = j01 * j01 + j11 * j11;
      const double g0 = j00 * rf + j10 * rd, g1 = j01 * rf + j11 * rd;
      bool improved = false;
      while (evaluations < kMaxSolveEvaluations && lambda < 1e12) {
        const double b00 = a00 * (1.0 + lambda) + 1e-300, b11 = a11 * (1.0 + lambda) + 1e-300;
        const double det = b00 * b11 - a01 * a01;
        if (!(det > 0.0) || !std::isfinite(det)) {
          lambda *= 10.0;
          continue;
        }
        double step0 = -(b11 * g0 - a01 * g1) / det, step1 = -(b00 * g1 - a01 * g0) / det;
        // Never more than a factor e in p0 or a few damping scales in p1 per iteration.
        const double limit = std::max(std::abs(step0), std::abs(step1) / (4.0 * std::max(std::abs(x1), p1_scale)));
        if (limit > 1.0) {
          step0 /= limit;
          step1 /= limit;
        }
        const Residual trial = residual(x0 + step0, x1 + step1);
        if (trial.ok && trial.norm_scaled() < best.norm_scaled()) {
          x0 += step0;
          x1 += step1;
          best = trial;
          lambda = std::max(lambda * 0.1, 1e-9);
          improved = true;
          break;
        }
        lambda *= 10.0;
      }
      if (!improved) break;
    }
  }
  out.p0 = std::exp(x0);
  out.p1 = x1;
  if (best.ok) {
    out.prediction = best.prediction;
    out.frequency_error = std::expm1(best.frequency);
    out.damping_error = best.damping;
    out.met = std::abs(out.frequency_error) <= kExactFrequencyTolerance &&
              std::abs(out.damping_error) <= kExactDampingTolerance;
  }
  return out;
}

}  // namespace softtune::engines

#include "softtune/sequential_impulse.h"

#include <Eigen/Eigenvalues>
#include <array>
#include <cmath>
#include <numbers>

namespace softtune {
namespace {

struct Joint {
  double gamma_impulse;  // gamma / h, 1/kg
  double bias_factor;    // beta / h, 1/s
  double soft_mass;      // 1 / (K + gamma / h), kg (Box2D's m_softMass)
};

// Each joint's softness from its own effective mass 1 / K (see the header).
Joint make_joint(double k_inv, const ChainModel& m) {
  const SpringConstants sc = spring_constants(1.0 / k_inv, m.omega, m.damping_ratio);
  const Softness s = softness_from_spring(sc.stiffness, sc.damping, m.h);
  const double gamma_impulse = impulse_gamma(s.gamma, m.h);
  return {gamma_impulse, bias_factor(s.beta, m.h), 1.0 / (k_inv + gamma_impulse)};
}

// The two joints of a model, computed once per model rather than per step.
struct ChainJoints {
  double inv_m1, inv_m2;  // 1/kg
  Joint j1, j2;
};

ChainJoints chain_joints(const ChainModel& model) {
  const double m1 = model.link_mass, m2 = model.link_mass * model.mass_ratio;
  return {1.0 / m1, 1.0 / m2, make_joint(1.0 / m1, model), make_joint(1.0 / m1 + 1.0 / m2, model)};
}

double zero_like(double) { return 0.0; }
template <typename Row>
Row zero_like(const Row&) {
  return Row::Zero();
}

// One step on the rows (x1, x2, v1, v2, Lambda1, Lambda2); Row is a double for one state, or an array
// holding several states side by side (the observation steps all unit states at once).
template <typename Row>
void step_rows(std::array<Row, 6>& r, const ChainModel& model, const ChainJoints& joints) {
  const double inv_m1 = joints.inv_m1, inv_m2 = joints.inv_m2;
  const Joint& j1 = joints.j1;
  const Joint& j2 = joints.j2;
  const Row c1 = r[0], c2 = r[1] - r[0];
  Row v1 = r[2], v2 = r[3];
  Row lambda1 = zero_like(r[4]), lambda2 = zero_like(r[5]);
  if (model.warm_start) {
    lambda1 = r[4];
    lambda2 = r[5];
    v1 += (lambda1 - lambda2) * inv_m1;
    v2 += lambda2 * inv_m2;
  }
  for (int it = 0; it < model.iterations; ++it) {
    // Joint 1: J = [1, 0].
    const Row d1 = -j1.soft_mass * (v1 + j1.bias_factor * c1 + j1.gamma_impulse * lambda1);
    lambda1 += d1;
    v1 += d1 * inv_m1;
    // Joint 2: J = [-1, 1].
    const Row d2 = -j2.soft_mass * ((v2 - v1) + j2.bias_factor * c2 + j2.gamma_impulse * lambda2);
    lambda2 += d2;
    v1 -= d2 * inv_m1;
    v2 += d2 * inv_m2;
  }
  r = {r[0] + model.h * v1, r[1] + model.h * v2, v1, v2, lambda1, lambda2};
}

}  // namespace

ChainState chain_step(const ChainState& s, const ChainModel& model) {
  std::array<double, 6> r = {s[0], s[1], s[2], s[3], s[4], s[5]};
  step_rows(r, model, chain_joints(model));
  return Eigen::Map<const ChainState>(r.data());
}

ChainMatrix chain_step_matrix(const ChainModel& model) {
  ChainMatrix a;
  for (int i = 0; i < 6; ++i) a.col(i) = chain_step(ChainState::Unit(i), model);
  return a;
}

double chain_spectral_radius(const ChainMatrix& a) {
  return Eigen::EigenSolver<ChainMatrix>(a, false).eigenvalues().cwiseAbs().maxCoeff();
}

ChainCase run_chain_case(const ChainModel& model, int observe_steps) {
  ChainCase c;
  c.mass_ratio = model.mass_ratio;
  c.iterations = model.iterations;
  c.warm_start = model.warm_start;
  c.frequency_ratio = model.omega * model.h / (2.0 * std::numbers::pi);
  c.damping_ratio = model.damping_ratio;
  c.spectral_radius = chain_spectral_radius(chain_step_matrix(model));
  c.predicted = classify_spectral_radius(c.spectral_radius);

  // All six unit states side by side: row i of the batch holds state component i of each.
  const ChainJoints joints = chain_joints(model);
  using Row = Eigen::Array<double, 1, 6>;
  std::array<Row, 6> rows;
  for (int i = 0; i < 6; ++i) {
    rows[i] = Row::Zero();
    rows[i](i) = 1.0;
  }
  bool finite = true;
  for (int n = 0; n < observe_steps && finite; ++n) {
    step_rows(rows, model, joints);
    // Checked every 64 steps: a blow-up stays non-finite once it overflows.
    if (n % 64 == 63 || n + 1 == observe_steps) {
      for (const Row& r : rows) finite = finite && r.allFinite();
    }
  }
  ChainMatrix map;
  for (int i = 0; i < 6; ++i) map.row(i) = rows[i].matrix();
  if (finite) {
    const double rho_n = chain_spectral_radius(map);
    if (std::isfinite(rho_n)) c.observed_spectral_radius = rho_n == 0.0 ? 0.0 : std::exp(std::log(rho_n) / observe_steps);
  }
  c.observed = c.observed_spectral_radius ? classify_spectral_radius(*c.observed_spectral_radius) : Verdict::unstable;
  return c;
}

ChainSweepSettings default_chain_sweep_settings() {
  ChainSweepSettings s;
  const int n = 16;
  for (int i = 0; i < n; ++i) s.frequency_ratios.push_back(1e-3 * std::pow(2.0 / 1e-3, i / double(n - 1)));
  return s;
}

ChainSweepResult run_chain_sweep(const ChainSweepSettings& s) {
  ChainSweepResult out;
  const int steps = std::max(1000, s.observe_steps);
  for (bool warm : s.warm_start) {
  for (double ratio : s.mass_ratios) {
    for (int iterations : s.iterations) {
      ChainLimit limit{ratio, iterations, warm, std::nullopt, std::nullopt, true};
      bool still_stable = true;
      for (double fr : s.frequency_ratios) {
        const ChainModel model{1.0, ratio, iterations, 2.0 * std::numbers::pi * fr / s.h, s.damping_ratio, s.h, warm};
        out.cases.push_back(run_chain_case(model, steps));
        const ChainCase& c = out.cases.back();
        if (c.observed != c.predicted) ++out.mismatches;
        if (c.predicted == Verdict::unstable) {
          still_stable = false;
          limit.stable_over_whole_scan = false;
        }
        if (still_stable) {
          limit.highest_stable_frequency_ratio = fr;
          limit.highest_stable_frequency_hz = fr / s.h;
        }
      }
      out.limits.push_back(limit);
    }
  }
  }
  return out;
}

}  // namespace softtune

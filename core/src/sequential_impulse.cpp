#include "softtune/sequential_impulse.h"

#include "softtune/chain_solvers.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
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

// Each joint's softness from its own effective mass 1 / K at the substep (see the header).
Joint make_joint(double k_inv, const ChainModel& m) {
  const double h = m.h / std::max(1, m.substeps);
  const SpringConstants sc = spring_constants(1.0 / k_inv, m.omega, m.damping_ratio);
  const Softness s = softness_from_spring(sc.stiffness, sc.damping, h);
  const double gamma_impulse = impulse_gamma(s.gamma, h);
  return {gamma_impulse, bias_factor(s.beta, h), 1.0 / (k_inv + gamma_impulse)};
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

// One Gauss-Seidel sweep over the two joints, C1 = c1 and C2 = c2 as given.
template <typename Row>
void sweep(const ChainModel& model, const ChainJoints& joints, const Row& c1, const Row& c2, Row& v1, Row& v2,
           Row& lambda1, Row& lambda2) {
  const Joint& j1 = joints.j1;
  const Joint& j2 = joints.j2;
  auto joint1 = [&] {  // J = [1, 0]
    const Row d1 = -j1.soft_mass * (v1 + j1.bias_factor * c1 + j1.gamma_impulse * lambda1);
    lambda1 += d1;
    v1 += d1 * joints.inv_m1;
  };
  auto joint2 = [&] {  // J = [-1, 1]
    const Row d2 = -j2.soft_mass * ((v2 - v1) + j2.bias_factor * c2 + j2.gamma_impulse * lambda2);
    lambda2 += d2;
    v1 -= d2 * joints.inv_m1;
    v2 += d2 * joints.inv_m2;
  };
  if (model.weight_joint_first) {
    joint2();
    joint1();
  } else {
    joint1();
    joint2();
  }
}

// One step on the rows (x1, x2, v1, v2, Lambda1, Lambda2); Row is a double for one state, or an array
// holding several states side by side (the observation steps all unit states at once).
template <typename Row>
void step_rows(std::array<Row, 6>& r, const ChainModel& model, const ChainJoints& joints) {
  const int substeps = std::max(1, model.substeps);
  const double h = model.h / substeps;
  const double scale = std::max(0.0, 1.0 - model.linear_damping * h);
  Row x1 = r[0], x2 = r[1], v1 = r[2], v2 = r[3];
  Row lambda1 = zero_like(r[4]), lambda2 = zero_like(r[5]);
  if (model.warm_start) {
    lambda1 = r[4];
    lambda2 = r[5];
  }
  for (int sub = 0; sub < substeps; ++sub) {
    if (scale != 1.0) {
      v1 *= scale;
      v2 *= scale;
    }
    if (sub > 0 && !model.warm_start && !model.substeps_carry_impulses) {
      lambda1 = zero_like(r[4]);
      lambda2 = zero_like(r[5]);
    }
    // Warm start: the carried impulses on the velocities (at sub 0 only with warm starting).
    if (model.warm_start || (sub > 0 && model.substeps_carry_impulses)) {
      v1 += (lambda1 - lambda2) * joints.inv_m1;
      v2 += lambda2 * joints.inv_m2;
    }
    const Row c1 = x1, c2 = x2 - x1;
    for (int it = 0; it < model.iterations; ++it) sweep(model, joints, c1, c2, v1, v2, lambda1, lambda2);
    x1 += h * v1;
    x2 += h * v2;
    for (int it = 0; it < model.relax_iterations; ++it) {
      if (model.relax_uses_new_positions) {
        const Row n1 = x1, n2 = x2 - x1;
        sweep(model, joints, n1, n2, v1, v2, lambda1, lambda2);
      } else {
        sweep(model, joints, c1, c2, v1, v2, lambda1, lambda2);
      }
    }
  }
  r = {x1, x2, v1, v2, lambda1, lambda2};
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

namespace {

// Observed per-step spectral radius: all six unit states stepped side by side (row i of the batch holds
// state component i of each); the end states are the columns of the simulated A^N, rooted. Every 32 steps
// the batch is rescaled by a power of two (exact in floating point) and the exponent kept, so a fast decay
// never reaches denormals (which cost ~100x per operation) and a growth never overflows: the observed
// radius is then the measured growth rate even of a blow-up. Empty when the simulation turned non-finite.
// K unit states side by side: all six, or (no warm starting) the four motion states only: a step then reads
// no Lambda input (step_rows starts each step's impulses at zero), so A's Lambda columns are exactly zero and
// so are A^N's; stepping them cost a third of the batch for nothing. The map gets those zero columns back,
// so the radius is the same number either way.
template <int K>
std::optional<double> observe_chain_states(const ChainModel& model, const ChainJoints& joints, int observe_steps) {
  using Row = Eigen::Array<double, 1, K>;
  std::array<Row, 6> rows;
  for (int i = 0; i < 6; ++i) {
    rows[i] = Row::Zero();
    if (i < K) rows[i](i) = 1.0;
  }
  long log2_scale = 0;
  for (int n = 0; n < observe_steps; ++n) {
    step_rows(rows, model, joints);
    if (n % 32 == 31 || n + 1 == observe_steps) {
      double peak = 0.0;
      for (const Row& r : rows) peak = std::max(peak, r.abs().maxCoeff());
      if (!std::isfinite(peak)) return std::nullopt;
      if (peak == 0.0) return 0.0;  // the map is nilpotent: every state reaches rest
      int e = 0;
      std::frexp(peak, &e);
      for (Row& r : rows) r = r * std::ldexp(1.0, -e);
      log2_scale += e;
    }
  }
  ChainMatrix map = ChainMatrix::Zero();
  for (int i = 0; i < 6; ++i) map.row(i).template head<K>() = rows[i].matrix();
  const double rho_n = chain_spectral_radius(map);
  if (!std::isfinite(rho_n)) return std::nullopt;
  if (rho_n == 0.0) return 0.0;
  return std::exp((std::log(rho_n) + static_cast<double>(log2_scale) * std::numbers::ln2) / observe_steps);
}

std::optional<double> observe_chain(const ChainModel& model, int observe_steps) {
  const ChainJoints joints = chain_joints(model);
  if (model.warm_start) return observe_chain_states<6>(model, joints, observe_steps);
  return observe_chain_states<4>(model, joints, observe_steps);
}

Verdict observed_verdict(const std::optional<double>& rho) {
  return rho ? classify_spectral_radius(*rho) : Verdict::unstable;
}

double omega_of(double frequency_ratio, double h) { return 2.0 * std::numbers::pi * frequency_ratio / h; }

}  // namespace

ChainCase run_chain_case(const ChainModel& model, int observe_steps) {
  ChainCase c;
  c.mass_ratio = model.mass_ratio;
  c.iterations = model.iterations;
  c.substeps = model.substeps;
  c.count = model.iterations;
  c.warm_start = model.warm_start;
  c.frequency_ratio = model.omega * model.h / (2.0 * std::numbers::pi);
  c.damping_ratio = model.damping_ratio;
  c.spectral_radius = chain_spectral_radius(chain_step_matrix(model));
  c.predicted = classify_spectral_radius(c.spectral_radius);
  c.observed_spectral_radius = observe_chain(model, observe_steps);
  c.observed = observed_verdict(c.observed_spectral_radius);
  return c;
}

ChainSweepSettings default_chain_sweep_settings() {
  ChainSweepSettings s;
  s.frequency_ratios = log_scan(1e-3, 2.0, 16);
  return s;
}

ChainLimit find_chain_limit(const ChainModelAt& model_at, std::span<const double> scan, int observe_steps,
                            std::span<const double> scan_radii) {
  const ChainModel base = model_at(scan.empty() ? 1e-3 : scan.front());
  ChainLimit limit;
  limit.mass_ratio = base.mass_ratio;
  limit.iterations = base.iterations;
  limit.substeps = base.substeps;
  limit.warm_start = base.warm_start;
  std::size_t next = 0;  // the scan's radii are used as far as they go
  const SpectralRadiusOf rho = [&](double fr) {
    if (next < scan_radii.size() && next < scan.size() && fr == scan[next]) return scan_radii[next++];
    return chain_spectral_radius(chain_step_matrix(model_at(fr)));
  };
  const StabilityLimit found = find_stability_limit(rho, scan);
  limit.kind = found.kind;
  limit.stable_over_whole_scan = found.kind == LimitKind::none_in_range;
  limit.highest_stable_frequency_ratio = found.stable_side;
  limit.lowest_unstable_frequency_ratio = found.unstable_side;
  limit.stable_side_radius = found.stable_side_radius;
  limit.unstable_side_radius = found.unstable_side_radius;
  if (found.stable_side) limit.highest_stable_frequency_hz = *found.stable_side / base.h;
  // The grid-only answer: the last scan point at or below the stable side.
  for (double fr : scan) {
    if (found.stable_side && fr <= *found.stable_side) limit.scan_highest_stable_frequency_ratio = fr;
  }
  if (found.kind == LimitKind::found) {
    limit.observed_stable_side = observed_verdict(observe_chain(model_at(*found.stable_side), observe_steps));
    limit.observed_unstable_side = observed_verdict(observe_chain(model_at(*found.unstable_side), observe_steps));
    limit.confirmed = *limit.observed_stable_side != Verdict::unstable && *limit.observed_unstable_side == Verdict::unstable;
  }
  return limit;
}

ChainLimit find_chain_limit(ChainSolver solver, int count, bool warm, double ratio, double zeta, double h,
                            std::span<const double> scan, int observe_steps, std::span<const double> scan_radii) {
  ChainLimit limit = find_chain_limit(
      [&](double fr) { return chain_model(solver, count, warm, ratio, omega_of(fr, h), zeta, h); }, scan,
      observe_steps, scan_radii);
  limit.solver = solver;
  limit.count = count;
  return limit;
}

namespace {

// The grid-only answer: the last scanned f h before the first predicted-unstable one.
ChainLimit grid_limit(ChainSolver solver, int count, bool warm, double ratio, const ChainSweepSettings& s,
                      const std::vector<double>& radii) {
  ChainLimit l;
  l.solver = solver;
  l.count = count;
  l.mass_ratio = ratio;
  l.warm_start = warm;
  l.kind = LimitKind::none_in_range;
  l.stable_over_whole_scan = true;
  for (std::size_t i = 0; i < radii.size(); ++i) {
    if (classify_spectral_radius(radii[i]) == Verdict::unstable) {
      l.kind = i == 0 ? LimitKind::unstable_at_lowest : LimitKind::found;
      l.stable_over_whole_scan = false;
      l.lowest_unstable_frequency_ratio = s.frequency_ratios[i];
      break;
    }
    l.highest_stable_frequency_ratio = l.scan_highest_stable_frequency_ratio = s.frequency_ratios[i];
    l.highest_stable_frequency_hz = s.frequency_ratios[i] / s.h;
  }
  return l;
}

}  // namespace

std::size_t chain_sweep_case_count(const ChainSweepSettings& s) {
  return s.solvers.size() * s.warm_start.size() * s.mass_ratios.size() * s.iterations.size() * s.frequency_ratios.size();
}

ChainSweepResult run_chain_sweep(const ChainSweepSettings& s, const ChainProgress& progress) {
  ChainSweepResult out;
  const int steps = std::max(1000, s.observe_steps);
  for (ChainSolver solver : s.solvers) {
    for (bool warm : s.warm_start) {
      for (double ratio : s.mass_ratios) {
        for (int count : s.iterations) {
          std::vector<double> radii;
          for (double fr : s.frequency_ratios) {
            ChainCase c = run_chain_case(chain_model(solver, count, warm, ratio, omega_of(fr, s.h), s.damping_ratio, s.h), steps);
            c.solver = solver;
            c.count = count;
            if (c.observed != c.predicted) ++out.mismatches;
            radii.push_back(c.spectral_radius);
            out.cases.push_back(c);
            if (progress && !progress()) return out;
          }
          if (s.bisect) {
            out.limits.push_back(find_chain_limit(solver, count, warm, ratio, s.damping_ratio, s.h, s.frequency_ratios, steps, radii));
            if (!out.limits.back().confirmed) ++out.unconfirmed_limits;
          } else {
            out.limits.push_back(grid_limit(solver, count, warm, ratio, s, radii));
          }
        }
      }
    }
  }
  return out;
}

}  // namespace softtune

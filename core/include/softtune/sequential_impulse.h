#pragma once
// The classic mass-ratio case: a light link (mass m1) hung from the ground by a soft constraint, a heavy
// weight (m2 = ratio * m1) hung from the link by a second one, solved the way game engines do: sequential
// impulses (projected Gauss-Seidel) with n iterations per step, then x += h v (Catto GDC 2011, "soft
// constraints in a solver"; Box2D 2.4 b2DistanceJoint::SolveVelocityConstraints).
//
// 1-D, displacements from rest: C1 = x1 (joint 1, ground to link), C2 = x2 - x1 (joint 2, link to
// weight). Each joint j has K_j = J_j M^-1 J_j^T (K1 = 1/m1, K2 = 1/m1 + 1/m2) and is tuned on its own
// effective mass 1/K_j: k_j = omega^2 / K_j, c_j = 2 zeta omega / K_j, softness at h (softness.h).
// One Gauss-Seidel update of joint j, impulse form (what Box2D 2.4 computes):
//   delta = -(J_j v + (beta_j / h) C_j + (gamma_j / h) Lambda_j) / (K_j + gamma_j / h),
//   Lambda_j += delta, v += M^-1 J_j^T delta,
// With warm starting (Box2D 2.4's default, b2DistanceJoint::InitVelocityConstraints) Lambda starts at last
// step's value and is applied to the velocities first; without it Lambda starts at 0. The whole step is
// linear in (x1, x2, v1, v2, Lambda1, Lambda2): its 6x6 matrix predicts stability, a simulation confirms it.
// (Without warm starting the Lambda columns are zero, so the matrix has the 4x4 motion's eigenvalues plus
// zeros.)

#include <Eigen/Core>
#include <optional>
#include <vector>

#include "softtune/discrete_analysis.h"

namespace softtune {

struct ChainModel {
  double link_mass = 1.0;     ///< m1, kg
  double mass_ratio = 1.0;    ///< m2 / m1
  int iterations = 1;         ///< Gauss-Seidel sweeps per step
  double omega = 0.0;         ///< rad/s, each joint's natural angular frequency on its effective mass
  double damping_ratio = 0.0;
  double h = 1.0 / 60.0;      ///< s
  bool warm_start = false;    ///< start each step from last step's accumulated impulses
};

/// (x1, x2, v1, v2, Lambda1, Lambda2): m, m, m/s, m/s, N s, N s.
using ChainState = Eigen::Matrix<double, 6, 1>;
using ChainMatrix = Eigen::Matrix<double, 6, 6>;

/// One step of the chain (see the header comment).
ChainState chain_step(const ChainState& s, const ChainModel& model);

/// The 6x6 step matrix, from stepping the unit states.
ChainMatrix chain_step_matrix(const ChainModel& model);

/// Largest |eigenvalue| of the step matrix (or any 6x6 matrix).
double chain_spectral_radius(const ChainMatrix& a);

struct ChainCase {
  double mass_ratio = 1.0;
  int iterations = 1;
  bool warm_start = false;
  double frequency_ratio = 0.0;  ///< f h
  double damping_ratio = 0.0;
  double spectral_radius = 0.0;  ///< of the step matrix
  Verdict predicted = Verdict::stable;
  std::optional<double> observed_spectral_radius;  ///< rho(simulated A^N)^(1/N); empty when non-finite
  Verdict observed = Verdict::stable;
};

/// Predicts (step matrix) and observes (N-step simulation from the 6 unit states) one configuration.
ChainCase run_chain_case(const ChainModel& model, int observe_steps);

struct ChainSweepSettings {
  std::vector<double> mass_ratios = {1, 10, 100, 1e3, 1e4, 1e5, 1e6};
  std::vector<int> iterations = {1, 2, 4, 8, 16};
  std::vector<bool> warm_start = {false, true};
  std::vector<double> frequency_ratios;  ///< f h, ascending; default: 16 log-spaced from 0.001 to 2
  double damping_ratio = 0.0;
  double h = 1.0 / 60.0;  ///< s
  int observe_steps = 1000;
};
ChainSweepSettings default_chain_sweep_settings();

/// Per (mass ratio, iterations): the highest f h below which every scanned frequency is predicted not
/// unstable; empty when even the lowest one is unstable.
struct ChainLimit {
  double mass_ratio = 1.0;
  int iterations = 1;
  bool warm_start = false;
  std::optional<double> highest_stable_frequency_ratio;
  std::optional<double> highest_stable_frequency_hz;  ///< at the settings' h
  bool stable_over_whole_scan = false;
};

struct ChainSweepResult {
  std::vector<ChainCase> cases;
  std::vector<ChainLimit> limits;
  std::size_t mismatches = 0;  ///< observed != predicted
};

ChainSweepResult run_chain_sweep(const ChainSweepSettings& settings);

}  // namespace softtune

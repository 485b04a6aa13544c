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
//
// The same loop, with the knobs below, is each engine's solver on this chain (chain_solvers.h): substeps
// (softness at h / substeps, warm start, sweeps, x += h v, relax sweeps, per substep: Box2D v3's b2SolverStep,
// Rapier's substeps, Jolt's collision steps), relax sweeps after the position update (Box2D v3's relax
// stage on the moved bodies; Rapier's stabilization pass on the substep's own right-hand side), the joint
// order (Box2D v3's graph colouring solves the link-weight joint first), impulses carried between
// substeps of one step even without warm starting (Box2D v3 zeroes them once per step), and a velocity
// scale per substep (Jolt's linear damping). The defaults are Box2D 2.4's step.

#include <Eigen/Core>
#include <array>
#include <functional>
#include <optional>
#include <span>
#include <vector>

#include "softtune/discrete_analysis.h"
#include "softtune/stability_limit.h"

namespace softtune {

/// The engines whose solver the chain models (chain_solvers.h).
enum class ChainSolver { box2d_v2_4, box2d_v3, jolt, rapier };
inline constexpr std::array<ChainSolver, 4> kAllChainSolvers = {ChainSolver::box2d_v2_4, ChainSolver::box2d_v3,
                                                                ChainSolver::jolt, ChainSolver::rapier};

struct ChainModel {
  double link_mass = 1.0;     ///< m1, kg
  double mass_ratio = 1.0;    ///< m2 / m1
  int iterations = 1;         ///< Gauss-Seidel sweeps per step
  double omega = 0.0;         ///< rad/s, each joint's natural angular frequency on its effective mass
  double damping_ratio = 0.0;
  double h = 1.0 / 60.0;      ///< s
  bool warm_start = false;    ///< start each step from last step's accumulated impulses
  int substeps = 1;           ///< substeps per step; softness at h / substeps
  int relax_iterations = 0;   ///< Gauss-Seidel sweeps after the position update, per substep
  bool relax_uses_new_positions = true;  ///< relax sweeps read C from the moved bodies (else the substep's)
  bool weight_joint_first = false;       ///< sweep joint 2 (link-weight) before joint 1 (ground-link)
  bool substeps_carry_impulses = false;  ///< impulses carried and re-applied between substeps of a step
  double linear_damping = 0.0;           ///< 1/s; v *= max(0, 1 - linear_damping h_sub) per substep (Jolt)
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
  ChainSolver solver = ChainSolver::box2d_v2_4;
  int count = 1;                 ///< the solver's chain_count_name (iterations or substeps)
  double mass_ratio = 1.0;
  int iterations = 1;            ///< Gauss-Seidel sweeps per substep (before the position update)
  int substeps = 1;
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
  std::vector<ChainSolver> solvers{kAllChainSolvers.begin(), kAllChainSolvers.end()};
  std::vector<double> mass_ratios = {1, 10, 100, 1e3, 1e4, 1e5, 1e6};
  std::vector<int> iterations = {1, 2, 4, 8, 16};  ///< each solver's count (chain_count_name)
  std::vector<bool> warm_start = {false, true};
  std::vector<double> frequency_ratios;  ///< f h, ascending; default: 16 log-spaced from 0.001 to 2
  double damping_ratio = 0.0;
  double h = 1.0 / 60.0;  ///< s
  int observe_steps = 1000;
  /// false: the grid-only answer (the last scan point before the first unstable one, no bisection and no
  /// confirmation), the benchmark's baseline.
  bool bisect = true;
};
ChainSweepSettings default_chain_sweep_settings();

/// Per (solver, mass ratio, count, warm start): the highest stable f h, found by bracketing on the scan
/// and bisecting to kLimitRelativeTolerance (stability_limit.h), then confirmed by simulating the bracket's
/// two sides: the stable side must not be observed unstable, the unstable side must be.
struct ChainLimit {
  ChainSolver solver = ChainSolver::box2d_v2_4;
  int count = 1;       ///< the solver's chain_count_name
  double mass_ratio = 1.0;
  int iterations = 1;  ///< Gauss-Seidel sweeps per substep
  int substeps = 1;
  bool warm_start = false;
  LimitKind kind = LimitKind::none_in_range;
  /// The bracket's stable side (the limit); when no limit is in range, the highest scanned f h; empty when
  /// even the lowest scanned f h is unstable.
  std::optional<double> highest_stable_frequency_ratio;
  std::optional<double> highest_stable_frequency_hz;  ///< at the settings' h
  std::optional<double> lowest_unstable_frequency_ratio;  ///< the bracket's unstable side
  std::optional<double> scan_highest_stable_frequency_ratio;  ///< the grid-only answer, for comparison
  double stable_side_radius = 0.0, unstable_side_radius = 0.0;
  std::optional<Verdict> observed_stable_side, observed_unstable_side;  ///< simulated at each side
  bool confirmed = true;  ///< the simulation agrees on both sides (true when there is nothing to confirm)
  bool stable_over_whole_scan = false;
};

struct ChainSweepResult {
  std::vector<ChainCase> cases;
  std::vector<ChainLimit> limits;
  std::size_t mismatches = 0;  ///< observed != predicted
  std::size_t unconfirmed_limits = 0;  ///< limits whose bracket sides the simulation contradicts
};

/// Called after each chain case (one f h of one solver, count, warm start and mass ratio; the bisection of
/// a limit after the last of its scan); returning false stops the sweep there (see SweepProgress).
using ChainProgress = std::function<bool()>;

ChainSweepResult run_chain_sweep(const ChainSweepSettings& settings, const ChainProgress& progress = {});

/// Cases run_chain_sweep runs: solvers x warm starts x mass ratios x counts x frequency ratios.
std::size_t chain_sweep_case_count(const ChainSweepSettings& settings);

/// One limit: `solver` with `count` and warm starting, at mass ratio and zeta, step h; bracketed on the
/// ascending f h `scan` (when `scan_radii` is given, the spectral radii already computed at the scan's
/// points), bisected, and confirmed by `observe_steps`-step simulations of both sides.
ChainLimit find_chain_limit(ChainSolver solver, int count, bool warm_start, double mass_ratio, double zeta,
                            double h, std::span<const double> scan, int observe_steps,
                            std::span<const double> scan_radii = {});

/// The same for any chain: `model_at(f h)` builds the model at a frequency ratio (its h is the step). The
/// limit's solver and count fields are left for the caller.
using ChainModelAt = std::function<ChainModel(double frequency_ratio)>;
ChainLimit find_chain_limit(const ChainModelAt& model_at, std::span<const double> scan, int observe_steps,
                            std::span<const double> scan_radii = {});

}  // namespace softtune

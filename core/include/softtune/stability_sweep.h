#pragma once
// Extreme-case stability sweep: for every method over a grid of frequency / step rate, damping ratio,
// mass, stiffness and step size, the prediction from the step matrix (discrete_analysis.h) against an
// observation by simulation.
//
// Observation: the method is stepped N >= 1000 times from the unit states (1, 0) and (0, 1). The two end
// states are the columns of the simulated N-step map M = A^N, and the observed per-step spectral radius
// is rho(M)^(1/N) (Gelfand: growth over N steps, rooted). Any non-finite state is an observed blow-up.
// Both are classified with classify_spectral_radius(): within 1 +- kMarginalBand is "marginal".

#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include "softtune/discrete_analysis.h"
#include "softtune/stability_limit.h"

namespace softtune {

/// How a case's spring was chosen: from a frequency ratio (f h) or directly from a stiffness.
enum class SweepFamily : std::uint8_t { frequency_ratio, stiffness };

/// Conditions worth a note on a case, as bit flags.
enum SweepWarning : std::uint8_t {
  kBeyondNyquist = 1 << 0,        ///< f h > 1/2: the step cannot represent the motion
  kFewStepsPerPeriod = 1 << 1,    ///< fewer than 4 steps per period (the talk's rule of thumb)
  kExactClampedToNyquist = 1 << 2,  ///< soft_exact matched the poles at the Nyquist limit instead
  kExactOverflowFallback = 1 << 3,  ///< soft_exact's k', c' overflow: standard softness used
  kMismatch = 1 << 4,             ///< observed verdict differs from the predicted one
};

struct SweepCase {
  Method method = Method::soft;
  SweepFamily family = SweepFamily::frequency_ratio;
  double frequency_ratio = 0.0;  ///< f h = f / step rate
  double damping_ratio = 0.0;
  double mass = 1.0;             ///< kg
  double stiffness = 0.0;        ///< N/m
  double h = 0.0;                ///< s
  double spectral_radius = 0.0;  ///< of the step matrix
  Verdict predicted = Verdict::stable;
  /// rho(A^N)^(1/N) from the simulation; empty when the simulation turned non-finite.
  std::optional<double> observed_spectral_radius;
  Verdict observed = Verdict::stable;
  std::uint8_t warnings = 0;     ///< SweepWarning flags
};

struct SweepSettings {
  std::vector<Method> methods{kAllMethods.begin(), kAllMethods.end()};
  std::vector<double> frequency_ratios;  ///< f h values of the frequency_ratio family
  std::vector<double> stiffnesses;       ///< N/m values of the stiffness family
  std::vector<double> damping_ratios;
  std::vector<double> masses;            ///< kg
  std::vector<double> steps;             ///< h values, s
  double max_stiffness = 1e12;           ///< N/m; frequency_ratio cases above it are not run
  int observe_steps = 1000;              ///< N, at least 1000
  bool step_limits = true;               ///< bisect each method's largest stable omega h (StepLimit)
};

/// The default sweep (docs/accuracy-and-stability.md): f h from 0.001 to 2, zeta in {0, 1e-3, 0.1, 0.5,
/// 1, 10, 1000}, mass 1e-6..1e6 kg, stiffness 1..1e12 N/m, h 1e-6..0.1 s, every method.
SweepSettings default_sweep_settings();

struct SweepSummary {
  std::size_t cases = 0;
  std::size_t predicted_stable = 0, predicted_marginal = 0, predicted_unstable = 0;
  std::size_t observed_unstable = 0;
  std::size_t mismatches = 0;       ///< observed != predicted
  std::size_t soft_blowups = 0;     ///< soft or soft_exact observed unstable (must be 0)
  std::size_t non_finite_values = 0;  ///< cases whose parameters or prediction are not finite (must be 0)
};

/// Per method and damping ratio: the largest stable omega h, bisected on the step matrix's spectral radius
/// (stability_limit.h) over kStepLimitScan, beside the closed form where one exists (max_stable_step).
/// omega h is the only parameter: each method's step matrix depends on omega h and zeta alone.
struct StepLimit {
  Method method = Method::soft;
  double damping_ratio = 0.0;
  StabilityLimit omega_h;                  ///< the bracket, in omega h (rad)
  std::optional<double> closed_form_omega_h;  ///< omega h_max from the Jury conditions; empty: none
};

/// The omega h range the step limits search: 1e-6 to 1e6 rad, 4 points per decade.
inline constexpr double kStepLimitLowest = 1e-6, kStepLimitHighest = 1e6;
inline constexpr int kStepLimitScanPoints = 49;

struct SweepResult {
  std::vector<SweepCase> cases;
  SweepSummary summary;
  std::vector<StepLimit> step_limits;  ///< methods x damping ratios of the settings
};

/// The largest stable omega h of one method at one damping ratio (see StepLimit).
StepLimit find_step_limit(Method m, double damping_ratio);

/// Predicts and observes one case. `c` carries the method and parameters; the rest is filled in.
SweepCase run_sweep_case(SweepCase c, int observe_steps);

/// Called after each case a sweep finishes (its natural unit); returning false stops the sweep there, and
/// the result holds the cases so far. Lets a job report progress and be cancelled (server/app/job_runner.h);
/// empty: never called (one test of an empty std::function per case, nothing measurable).
using SweepProgress = std::function<bool()>;

/// Every case of the grid; `progress` after each one.
SweepResult run_sweep(const SweepSettings& settings, const SweepProgress& progress = {});

/// Cases run_sweep runs for `settings`: methods x steps x masses x damping ratios x (the frequency ratios
/// whose stiffness is within max_stiffness + stiffnesses), the same skip rule as run_sweep's.
std::size_t sweep_case_count(const SweepSettings& settings);

/// Observed per-step spectral radius of a method by simulation (see the header comment); empty when
/// non-finite.
std::optional<double> observed_spectral_radius(Method m, const StepModel& model, int steps);

}  // namespace softtune

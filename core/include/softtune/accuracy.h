#pragma once
// Work-precision report (docs/accuracy-and-stability.md): each method at a range of step
// rates and substep counts runs the standard scenario (released from rest displaced by x0 = 1), and each
// run is scored against the analytic solution and timed. From the rows, the cheapest configuration that
// meets an error budget is recommended.

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "softtune/methods.h"

namespace softtune::limits {
inline constexpr std::size_t kMaxStepRates = 16;        ///< entries of step_rates
inline constexpr std::size_t kMaxSoftSubsteps = 8;      ///< entries of soft_substeps
inline constexpr int kMaxSoftSubstepCount = 64;         ///< each soft_substeps entry, 1..64
inline constexpr double kMinErrorBudget = 1e-12, kMaxErrorBudget = 100.0;  ///< relative to the amplitude
inline constexpr int kMaxTimingRepeats = 51;
inline constexpr double kMinPeriods = 3.0;              ///< duration_s covers at least this many periods
inline constexpr double kMaxAccuracyStepsPerRow = 2e6;  ///< fps * substeps * duration_s
inline constexpr double kDefaultDurationNoSpringS = 1.0;  ///< s, duration when the frequency is 0
/// The default duration also covers this many frames of the lowest step rate, so a fast spring at a low
/// rate is still sampled enough to score (and to fit its poles).
inline constexpr double kMinFramesAtLowestRate = 8.0;
}  // namespace softtune::limits

namespace softtune {

/// A run outside core (the CLI injects Box2D 2.4's distance joint, engines/box2d_v2_4): the oscillator
/// (kg, N/m, N s/m) released at x0 (m) from rest, stepped `steps` times with step h (s). Returns the
/// position after every step, x0 first (steps + 1 samples).
struct EngineRunner {
  std::string name;  ///< the row's method name, e.g. "box2d_distance_joint"
  std::function<std::vector<double>(const Oscillator& spring, double x0, double h, int steps)> run;
};

/// Reads a monotonic clock in seconds. Injectable so tests are deterministic.
using SecondsClock = std::function<double()>;

/// The steady clock (std::chrono::steady_clock) in seconds.
double steady_clock_seconds();

struct AccuracySettings {
  double mass = 1.0;           ///< kg, effective mass
  double omega = 0.0;          ///< rad/s, natural angular frequency asked
  double damping_ratio = 0.0;  ///< zeta asked
  std::vector<double> step_rates_hz = {30, 60, 120, 240, 480};  ///< fps values (frames per second)
  std::vector<int> soft_substeps = {1, 2, 4, 8};  ///< substep counts run for soft and soft_exact
  double duration_s = 1.0;     ///< s, simulated time (the caller makes it at least 3 periods)
  double error_budget = 0.05;  ///< max position error relative to the amplitude (x0)
  int timing_repeats = 5;      ///< timed batches per row; the median is reported
  /// Steps per timed batch at least this many (short runs repeated) so a batch is well above the
  /// clock's resolution.
  int min_steps_per_batch = 1024;
  SecondsClock clock = steady_clock_seconds;
  std::optional<EngineRunner> engine;  ///< an extra row per step rate when set
};

/// One configuration: a method at one frame rate and substep count.
struct AccuracyRow {
  std::string method;       ///< method_name() or the engine's name
  std::optional<Method> core_method;  ///< empty for the engine row
  double fps = 60.0;        ///< Hz, frames per second; errors are sampled once per frame
  int substeps = 1;
  double h = 0.0;           ///< s, the (sub)step
  int frames = 0;           ///< frames simulated
  bool blew_up = false;     ///< non-finite, or the fitted trajectory poles grow (|z| > 1 + kGrowthTolerance)
  std::optional<double> max_error;  ///< max |x - x_exact| / |x0| over the frames; empty when blew_up
  std::optional<double> rms_error;  ///< root mean square of the same; empty when blew_up
  std::optional<double> pole_frequency_hz;       ///< from the step matrix's eigenvalues (core methods)
  std::optional<double> pole_damping_ratio;
  std::optional<double> pole_spectral_radius;    ///< per (sub)step
  std::optional<double> trajectory_frequency_hz;  ///< from the sampled positions (trajectory_fit.h)
  std::optional<double> trajectory_damping_ratio;
  double cpu_seconds_per_sim_second = 0.0;  ///< median over timing_repeats
  std::vector<double> positions;  ///< m, x once per frame, x0 first; stops early when the run blew up
};

/// Relative growth per frame of the fitted trajectory poles above which a run counts as growing.
/// Round-off in the fit of an undamped (marginal) double-precision run stays far below it.
inline constexpr double kGrowthTolerance = 1e-6;
/// A run stops once |x| exceeds this multiple of |x0|: it has blown up.
inline constexpr double kBlowUpAmplitude = 1e100;

/// Why the recommended row was chosen, as data (the codec writes the sentence).
struct Recommendation {
  std::optional<std::size_t> row;        ///< index into rows; empty when no row meets the budget
  double error_budget = 0.0;
  std::size_t rows_meeting_budget = 0;
  std::optional<std::size_t> most_accurate;  ///< lowest max_error among rows that did not blow up
  /// Rows whose cost is within this factor of the cheapest passing row count as equally cheap (timing
  /// noise); among them the lowest max_error wins.
  double cost_tie_factor = 1.1;
};

struct AccuracyReport {
  std::vector<AccuracyRow> rows;
  double duration_s = 0.0;
  Recommendation recommendation;
};

/// The standard scenario's initial state: x0 = 1 m, v0 = 0.
inline constexpr double kStandardX0 = 1.0;

/// Runs every row. Settings must be valid (positive rates, duration, substeps >= 1).
AccuracyReport run_accuracy(const AccuracySettings& settings);

/// The cheapest row with max_error <= budget that did not blow up (ties: see Recommendation).
Recommendation recommend(const std::vector<AccuracyRow>& rows, double error_budget);

/// Errors of a sampled trajectory x[n] at t = n dt against the analytic solution from (x0, 0):
/// max and RMS of |x[n] - x_exact(n dt)| / |x0| over n = 1..N.
struct TrajectoryError {
  double max_error = 0.0;
  double rms_error = 0.0;
};
TrajectoryError trajectory_error(const std::vector<double>& x, double dt, double omega, double zeta);

}  // namespace softtune

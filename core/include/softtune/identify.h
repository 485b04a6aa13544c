#pragma once
// Identification (issue 19): from a trajectory recorded in any engine -- a time column and one or more probe
// columns (a position or an angle per probe) -- to what the engine did: its natural frequency, damping ratio,
// equilibrium and discrete poles, how well a linear second-order motion explains the samples, and a quality
// verdict. Pure math on vectors; no I/O (the CSV and JSON readers are in server/codec/identify_codec.h).
//
// Method, in four steps (docs/identify.md):
//  1. Sampling. The sample interval is the least-squares slope of time against sample index, so noise in
//     the time column (a wall clock, rounding) averages out. When a timestamp strays more than
//     kIdentifyGridTolerance intervals from that uniform grid the sampling is not uniform: the probes are
//     resampled onto a uniform grid at the median interval by linear interpolation (verdict
//     non_uniform_sampling).
//  2. Step rate. A game that records every rendered frame while physics steps at a lower fixed rate holds
//     each step's value for one or more frames. When values repeat while the probe is still moving and the
//     held-out steps fit a linear motion better than the raw samples, each run of equal values is one engine
//     step: the fit runs on the steps, and the step rate is (steps - 1) / (time of the last step's first
//     sample - time of the first).
//  3. Poles. Prony's method (fit_response, response_fit.h) gives the discrete poles z1, z2 of the recurrence
//     x[n+2] = p x[n+1] + q x[n] + b. It fits the equation error, which noise in the samples biases (towards
//     more damping); so the poles are then refined by variable projection on the output error: for given
//     (p, q) the motion is x[n] = x_e + a u[n] + w_b w[n], u and w the recurrence's solutions from (1, 0)
//     and (0, 1), linear in (x_e, a, w_b); Gauss-Newton with Levenberg-Marquardt damping moves (p, q), with
//     Kaufman's Jacobian (the derivative of u and w obeys the same recurrence, forced by u and w). Every
//     probe shares the poles in the joint fit; each probe also gets its own.
//  4. Reading. s = ln(z) / interval gives omega = |s|, zeta = -Re(s) / |s| (achieved_from_poles, as the
//     discrete analysis reads its own integrators).

#include <complex>
#include <cstddef>
#include <optional>
#include <string_view>
#include <vector>

namespace softtune {

/// Bounds of a recording (checked by validate_recording before any work; docs/identify.md lists them).
inline constexpr std::size_t kIdentifyMaxSamples = 100'000;  ///< rows
inline constexpr std::size_t kIdentifyMaxProbes = 16;        ///< probe columns beside the time column
inline constexpr std::size_t kIdentifyMaxCells = 400'000;    ///< rows x probe columns
inline constexpr std::size_t kIdentifyMinSamples = 16;       ///< fewer moving samples: too_short
/// A timestamp further than this many sample intervals from the least-squares uniform grid makes the
/// sampling non-uniform (resampled). Jitter below it is timing noise and is averaged out.
inline constexpr double kIdentifyGridTolerance = 0.25;
/// Output-error residual (RMS of what the fit leaves / RMS motion about equilibrium) above which the
/// recording is too_noisy: a signal-to-noise ratio below about 10 in RMS.
inline constexpr double kIdentifyNoisyResidual = 0.1;
/// Fewer oscillation cycles than this in the fitted window (damped frequency x duration) is too_short.
inline constexpr double kIdentifyMinCycles = 0.5;
/// This many equal consecutive samples at a probe's largest or smallest value, before its settled tail, is
/// clipped (a joint limit, a saturated sensor, a position clamp).
inline constexpr int kIdentifyClipRun = 3;
/// Levenberg-Marquardt iterations of the output-error refinement, and the relative cost gain below which
/// a step ends it.
inline constexpr int kIdentifyMaxIterations = 60;
inline constexpr double kIdentifyStopGain = 1e-10;
/// The first leading window the refinement of a long record starts on (samples; it grows by 4 each time).
inline constexpr long kIdentifyWarmWindow = 256;

/// What may be wrong with a recording, as data; an empty list means the fit can be trusted.
enum class IdentifyVerdict {
  too_short,             ///< fewer than kIdentifyMinSamples moving samples, or under kIdentifyMinCycles cycles
  too_noisy,             ///< residual above kIdentifyNoisyResidual
  not_oscillating,       ///< no complex pole pair (over-damped or no motion): frequency and ratio are weak
  non_uniform_sampling,  ///< timestamps off a uniform grid: resampled by linear interpolation
  clipped,               ///< a plateau at the largest or smallest value: the motion was limited
};

/// snake_case name, e.g. "non_uniform_sampling".
std::string_view identify_verdict_name(IdentifyVerdict verdict);

/// A sampled trajectory: time (s) and one column per probe, each as long as the time column.
struct Recording {
  std::vector<double> time_s;
  std::vector<std::vector<double>> probes;
};

/// Where a recording breaks a rule: the 0-based sample (row) and column (0 = time, 1 + i = probe i).
struct RecordingError {
  std::size_t row = 0;
  std::size_t column = 0;
  std::string_view rule;  ///< a static sentence, e.g. "must be later than the previous row's time"
};

/// The first rule the recording breaks, or nothing: at least two rows and one probe, at most
/// kIdentifyMaxSamples rows, kIdentifyMaxProbes probes and kIdentifyMaxCells values, every column as long as the time column, every
/// value finite, time strictly increasing.
std::optional<RecordingError> validate_recording(const Recording& recording);

/// The motion fitted to one probe, or to all probes sharing their poles.
struct MotionFit {
  std::optional<double> frequency_hz;         ///< Hz, natural frequency |s| / 2 pi; empty when the fit fails
  std::optional<double> damping_ratio;        ///< -Re(s) / |s|
  std::optional<double> damped_frequency_hz;  ///< Hz, Im(s) / 2 pi: the visible oscillation; 0 when none
  std::optional<std::complex<double>> z1, z2;  ///< discrete poles per fit interval
  std::optional<double> residual;  ///< output error: RMS(x - fit) / RMS(x - x_e) over the window; 0 exact
  std::vector<double> equilibrium;  ///< per probe fitted, x_e (the value it decays to), in the probe's unit
  int samples_used = 0;             ///< samples per probe in the fit window
  /// Per probe, the fitted motion x_e + a u[n] + w_b w[n] at each fit interval over the window (for plots).
  std::vector<std::vector<double>> fitted;
  std::vector<IdentifyVerdict> verdicts;
};

struct Identification {
  std::size_t samples = 0;           ///< rows recorded
  double sample_interval_s = 0.0;    ///< s, least-squares slope of time against row
  double sample_rate_hz = 0.0;       ///< 1 / sample_interval_s
  double grid_deviation = 0.0;       ///< largest |t - uniform grid| in sample intervals
  bool resampled = false;            ///< non-uniform: fitted on a uniform grid at the median interval
  std::optional<double> step_rate_hz;  ///< Hz, the engine's step rate when held frames reveal it
  double fit_interval_s = 0.0;       ///< s, the interval the poles are per (1 / step rate when seen)
  MotionFit joint;                   ///< every probe with shared poles (the answer's headline)
  std::vector<MotionFit> probes;     ///< each probe on its own, in column order
  std::vector<IdentifyVerdict> verdicts;  ///< the union of every fit's verdicts and the sampling's
};

/// Identifies a recording that validate_recording accepted. Bounded: O(samples x probes x iterations).
Identification identify(const Recording& recording);

}  // namespace softtune

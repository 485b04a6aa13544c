#include "app/accuracy_cost.h"

#include <algorithm>
#include <cmath>

#include "app/cost_drivers.h"

namespace softtune::app {
namespace {

// Rates measured on the reference machine (accuracy_cost.h).
constexpr double kStepSeconds = 25e-9, kFrameSeconds = 100e-9, kBox2DFrameSeconds = 3e-6;
constexpr double kFrameBytes = 8, kSvgPointBytes = 80;
constexpr int kCoreRowsOnce = 3;  // explicit, semi-implicit and implicit Euler: one row per rate

// The default report's own size, what the drivers' factors compare with.
constexpr double kDefaultRates = 5, kDefaultTimingRepeats = 5, kDefaultMaxSubsteps = 8;

}  // namespace

RequestCost accuracy_cost(const codec::AccuracyRequest& q, bool box2d_row, bool svg) {
  const AccuracySettings& s = q.settings;
  const double repeats = std::max(1, s.timing_repeats);
  const double batch_steps = std::max(1, s.min_steps_per_batch);
  double seconds = 0.0, bytes = 0.0, frames_total = 0.0;
  int rows = 0;
  auto core_row = [&](double frames, int substeps) {
    const double steps = frames * substeps;
    seconds += frames * kFrameSeconds + (steps + repeats * std::max(steps, batch_steps)) * kStepSeconds;
    bytes += (frames + 1) * kFrameBytes;
    ++rows;
  };
  for (double fps : s.step_rates_hz) {
    const double frames = std::max(1.0, std::round(s.duration_s * fps));
    frames_total += frames;
    for (int i = 0; i < kCoreRowsOnce; ++i) core_row(frames, 1);
    for (int n : s.soft_substeps) {
      core_row(frames, n);
      core_row(frames, n);
    }
    if (box2d_row && q.box2d) {
      seconds += (1 + repeats) * frames * (kBox2DFrameSeconds + kFrameSeconds);
      bytes += 2 * (frames + 1) * kFrameBytes;
      ++rows;
    }
    if (svg && fps == q.tune.fps) bytes += 2.0 * (kCoreRowsOnce + 2 + 1) * (frames + 1) * kSvgPointBytes;
  }
  RequestCost cost;
  cost.cpu_seconds = seconds;
  cost.peak_bytes = bytes;
  cost.work = std::to_string(rows) + " rows over " + std::to_string(static_cast<long long>(frames_total)) +
              " frames per method, each run " + std::to_string(static_cast<int>(repeats) + 1) + " times";

  const double max_rate = *std::max_element(s.step_rates_hz.begin(), s.step_rates_hz.end());
  const double max_substeps = *std::max_element(s.soft_substeps.begin(), s.soft_substeps.end());
  const double f = requested_frequency_hz(q.tune);
  const double default_duration = f > 0.0 ? limits::kMinPeriods / f : limits::kDefaultDurationNoSpringS;
  CostDrivers drivers;
  drivers.add("duration_s", s.duration_s / default_duration);
  drivers.add("step_rates", std::max(s.step_rates_hz.size() / kDefaultRates, max_rate / 480.0));
  drivers.add("timing_repeats", repeats / kDefaultTimingRepeats);
  drivers.add("soft_substeps", max_substeps / kDefaultMaxSubsteps);
  if (box2d_row && q.box2d) drivers.add("box2d", 1.0 + 1e-9);
  cost.fields = drivers.fields();
  return cost;
}

}  // namespace softtune::app

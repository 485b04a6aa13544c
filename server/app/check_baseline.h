#pragma once
// The baseline of `softtune check --baseline FILE`: every figure a check measured (each probe's frequency,
// damping ratio, overshoot, settle time and largest value; the scene's constraint error, finiteness and
// staying in the world), per preset and rate, recorded once (`--update-baseline`) and compared on every
// later run. A regression is usually a drift, not a hard failure ("the suspension's frequency moved from 3.0
// to 2.7 Hz after the engine update"): a figure further from its baseline than its tolerance fails the case.
// File format: docs/preset-ci.md.

#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "softtune/scene/expectations.h"

namespace softtune::app {

/// One measured figure: "drag.frequency_hz", "max_constraint_error", "box2d_reduced:plank.damping_ratio".
/// Empty value: undefined (no fit, never settled).
struct Figure {
  std::string name;
  std::optional<double> value;
};

/// Allowed drift: |value - baseline| <= absolute + relative |baseline|.
struct Tolerance {
  double absolute = 0.0;
  double relative = 0.0;
};

/// The figures of a check, in a fixed order: the scene-wide ones, then each probe's; runs on a second mass
/// model are prefixed with its name and ":".
std::vector<Figure> measured_figures(const scene::CheckResult& check);

/// The default tolerance of a figure, by its last part (frequency_hz: 1 %; damping_ratio and overshoot:
/// 0.01; settle_frames: 1 frame; settle_s: 0.02 s; max_abs_value: 2 %; max_constraint_error: 10 % + 0.1 mm;
/// finite, in_world: exact).
Tolerance default_tolerance(const std::string& figure);

struct Baseline {
  /// case key ("mouse@60x1") -> figure name -> value (empty: undefined when recorded)
  std::map<std::string, std::map<std::string, std::optional<double>>> cases;
  /// figure name ("drag.frequency_hz") or its last part ("frequency_hz") -> tolerance; a full name wins.
  std::map<std::string, Tolerance> tolerances;
};

/// A figure that left its tolerance (or appeared, or disappeared).
struct Drift {
  std::string figure;
  std::optional<double> baseline;
  std::optional<double> value;
  Tolerance tolerance;
  bool missing = false;  ///< in the baseline, no longer measured
};

/// The tolerance `baseline` gives `figure`: a full-name entry, else a last-part entry, else the default.
Tolerance tolerance_for(const Baseline& baseline, const std::string& figure);

/// The drifts of one case against its baseline entry; nothing when the case has no entry (see has_case).
std::vector<Drift> compare_with_baseline(const Baseline& baseline, const std::string& case_key,
                                         const std::vector<Figure>& figures);

/// "drag.frequency_hz: baseline 2, now 2.5 (tolerance 0.02)": the figure, its baseline and its new value.
std::string drift_message(const Drift& d);

/// Reads a baseline document; Problem (422) naming the field ("baseline.cases.mouse@60x1.drag.frequency_hz")
/// when it is not one. `field` is the prefix of those names.
Baseline decode_baseline(const nlohmann::json& doc, const std::string& field);

/// The baseline document, with every tolerance in use written out so a studio can edit them.
nlohmann::json encode_baseline(const Baseline& baseline);

/// Reads FILE (Problem 404 when absent, 422 when malformed).
Baseline read_baseline_file(const std::string& path);

/// Writes FILE (Problem 500 naming it when it cannot be written).
void write_baseline_file(const std::string& path, const Baseline& baseline);

}  // namespace softtune::app

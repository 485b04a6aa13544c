#pragma once
// The accuracy contract (`softtune accuracy`, later POST /api/v1/accuracy): a tune request plus the
// report's own fields in, the work-precision report out as JSON, CSV or SVG. Field list:
// docs/accuracy-and-stability.md, "softtune accuracy".

#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "softtune/accuracy.h"
#include "softtune/tune.h"

namespace softtune::codec {

/// A decoded accuracy request: the tune part and the report settings derived from it.
struct AccuracyRequest {
  TuneRequest tune;
  AccuracySettings settings;
  bool box2d = true;  ///< run the Box2D row when a runner is given
};

/// Decodes and validates; throws Problem (422) naming the field and the rule.
AccuracyRequest decode_accuracy_request(const nlohmann::json& doc);

/// Runs the report; `engine` adds its row per step rate (the CLI passes Box2D's runner) and the
/// `box2d_distance_joint` stage. `clock` replaces the steady clock (tests).
AccuracyReport run_accuracy_report(const AccuracyRequest& request, const std::optional<EngineRunner>& engine,
                                   const SecondsClock& clock = steady_clock_seconds);

/// The JSON response: rows, duration_s, error_budget, recommendation (with reason), stages.
nlohmann::json encode_accuracy_report(const AccuracyRequest& request, const AccuracyReport& report,
                                      bool engine_ran);

/// decode + run + encode.
nlohmann::json run_accuracy(const nlohmann::json& doc, const std::optional<EngineRunner>& engine = std::nullopt);

/// The rows of an encoded report as CSV (one line per row, nested fields flattened with "_").
std::string accuracy_csv(const nlohmann::json& encoded);

/// The four plots as one SVG: response, error over time, work-precision, stability map.
std::string accuracy_svg(const AccuracyRequest& request, const AccuracyReport& report);

}  // namespace softtune::codec

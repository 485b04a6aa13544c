#pragma once
// The accuracy use case, shared by `softtune accuracy` and POST /api/v1/accuracy: the work-precision
// report, with the Box2D 2.4 distance joint row (engines/box2d_v2_4) when the request keeps it, as JSON,
// CSV or SVG.

#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "app/answer.h"
#include "codec/accuracy_codec.h"

namespace softtune::app {

/// Runs the report, refused (422) first when over the budget (accuracy_cost.h); `engine` adds its row per step rate and the `box2d_distance_joint` stage. `clock`
/// replaces the steady clock (tests).
AccuracyReport run_accuracy_report(const codec::AccuracyRequest& request, const std::optional<EngineRunner>& engine,
                                   const SecondsClock& clock = steady_clock_seconds);

/// decode + run + encode.
nlohmann::json run_accuracy(const nlohmann::json& doc, const std::optional<EngineRunner>& engine = std::nullopt);

/// The Box2D 2.4 row's runner (the real engine, engines/box2d_v2_4).
EngineRunner box2d_row();

/// The report for a request in `format`, with the Box2D row: what the CLI prints and the route sends.
Answer accuracy_answer(const nlohmann::json& request, Format format);

/// The rows of an encoded report as CSV (one line per row, nested fields flattened with "_").
std::string accuracy_csv(const nlohmann::json& encoded);

/// The four plots as one SVG: response, error over time, work-precision, stability map.
std::string accuracy_svg(const codec::AccuracyRequest& request, const AccuracyReport& report);

}  // namespace softtune::app

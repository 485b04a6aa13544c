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

/// A row's name in every output: the method, with " xN substeps" when it substeps.
std::string row_label(const AccuracyRow& row);

/// Decodes and validates; throws Problem (422) naming the field and the rule.
AccuracyRequest decode_accuracy_request(const nlohmann::json& doc);

/// The JSON response: rows, duration_s, error_budget, recommendation (with reason), stages.
nlohmann::json encode_accuracy_report(const AccuracyRequest& request, const AccuracyReport& report,
                                      bool engine_ran);

}  // namespace softtune::codec

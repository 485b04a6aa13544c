#pragma once
// The tune contract (shared by `softtune tune` and POST /api/v1/tune): JSON <-> TuneRequest/TuneResult.

#include <nlohmann/json.hpp>

#include "codec/json_reader.h"
#include "softtune/analytic.h"
#include "softtune/effective_mass_terms.h"
#include "softtune/tune.h"

namespace softtune::codec {

/// Decodes and validates a tune request; throws Problem (422) naming the field and the rule.
TuneRequest decode_tune_request(const nlohmann::json& doc);

/// Reads the tune fields from an object that may also hold other fields (scenes, accuracy requests);
/// the caller calls finish(). Validates.
TuneRequest read_tune_fields(ObjectReader& r);

/// The response object (field list: docs/api.md, "softtune tune").
nlohmann::json encode_tune_result(const TuneRequest& request, const TuneResult& result);

/// {duration_s, step_matrix, smooth: {dt_s, x}}: the exact motion a plot draws the methods against, so a
/// client needs no copy of the closed form (docs/api.md, "exact_motion").
nlohmann::json encode_exact_motion(const ExactMotion& motion);

/// {body_a: {translational, rotational}, body_b: {...}}: the terms of 1 / m_eff (docs/api.md).
nlohmann::json encode_mass_terms(const InverseMassTerms& terms);

}  // namespace softtune::codec

#pragma once
// JSON <-> the verify contract (`softtune verify`, POST /api/v1/verify): a tune request plus the real
// engines to run it in, and per engine measured against predicted and requested.

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "softtune/engines/verify.h"
#include "softtune/tune.h"

namespace softtune::codec {

struct VerifyRequest {
  TuneRequest tune;
  std::vector<const engines::RealEngine*> engines;  ///< in the order asked; empty runs none
  engines::VerifyOptions options;
};

/// Most trajectory samples an answer carries per run (longer runs are strided).
inline constexpr std::size_t kVerifyMaxPlotSamples = 1000;
/// Most engine names a request may list.
inline constexpr std::size_t kVerifyMaxEngines = 16;

VerifyRequest decode_verify_request(const nlohmann::json& doc);

nlohmann::json encode_verify_result(const VerifyRequest& request, const TuneResult& tuned,
                                    const std::vector<engines::EngineVerification>& runs);

}  // namespace softtune::codec

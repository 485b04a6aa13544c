#pragma once
// The check contract's options as a JSON request, read the same way for `softtune check` (which builds the
// request from its flags) and POST /api/v1/check: fps, substeps, shard, and for the route the presets, inline
// scenes, baseline and format. Every field bounded before work starts (docs/preset-ci.md).

#include <nlohmann/json.hpp>
#include <string>

#include "app/check_app.h"
#include "codec/json_reader.h"

namespace softtune::app {

/// Largest lists of a check request: preset names, inline scenes.
inline constexpr std::size_t kMaxCheckPresets = 256, kMaxCheckScenes = 16;

/// "I/N" with 1 <= I <= N <= kMaxShards; Problem (422) naming `field` otherwise.
Shard parse_shard(const std::string& text, const std::string& field);

/// Reads "fps" (up to 16 frame rates, Hz), "substeps" (up to 16 counts) and "shard" ("I/N") into options.
void read_check_options(codec::ObjectReader& r, CheckOptions& options);

/// What POST /api/v1/check answers: the JSON report, or JUnit XML when the request asks "format": "junit".
struct CheckAnswer {
  bool junit = false;
  nlohmann::json json;
  std::string xml;
};

/// POST /api/v1/check: {"presets": [NAME...]?, "scenes": [{scene}...]?, "fps"?, "substeps"?, "shard"?,
/// "baseline": {baseline document}?, "format": "json" | "junit"?}; neither presets nor scenes: every preset of
/// `presets_dir`. Refused (422 naming presets, scenes, fps and substeps) when its work estimate exceeds
/// kMaxCheckWork.
CheckAnswer run_check_request(const nlohmann::json& request, const std::string& presets_dir);

}  // namespace softtune::app

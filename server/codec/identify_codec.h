#pragma once
// JSON <-> the identify contract (`softtune identify`, POST /api/v1/identify; docs/identify.md): a recorded
// trajectory (JSON arrays, or CSV text), optionally the tune request it was tuned from, the engine it ran
// in, what was typed and earlier rounds; answered with what the engine did and what to type instead.

#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "codec/csv_recording.h"
#include "softtune/identify.h"
#include "softtune/identify_correction.h"
#include "softtune/tune.h"

namespace softtune::codec {

/// Most earlier rounds (`previous`) a request may carry.
inline constexpr std::size_t kIdentifyMaxPrevious = 4;
/// Lowest typed damping ratio a request may carry (a correction types negative ones: identify_correction.h).
inline constexpr double kIdentifyLowestTypedRatio = -1.0;
/// Longest engine name (bytes).
inline constexpr std::size_t kIdentifyMaxEngineName = 64;
/// Most samples per probe the answer's `plot` carries (longer recordings are strided).
inline constexpr std::size_t kIdentifyMaxPlotSamples = 1000;

/// What was typed: a frequency and damping ratio, or a stiffness and damping (converted with the request's
/// effective mass: omega = sqrt(k / m), zeta = c / (2 sqrt(k m))).
struct TypedValues {
  std::optional<ResponseValues> response;
  std::optional<SpringConstants> spring;  ///< N/m and N s/m
};

/// One earlier recording: its trajectory or its measured response, and what was typed for it.
struct PreviousRound {
  std::optional<NamedRecording> recording;
  std::optional<ResponseValues> measured;
  TypedValues typed;
};

struct IdentifyRequest {
  NamedRecording recording;
  std::optional<TuneRequest> tune;     ///< `request`: the tune contract the engine was tuned with
  std::optional<std::string> engine;   ///< a modelled engine's name (engine_models()) or any other
  std::optional<TypedValues> typed;    ///< default: the request's frequency and damping ratio
  std::vector<PreviousRound> previous;  ///< oldest first
  bool negative_damping = true;  ///< whether the engine takes a negative damping (a correction may type one)
};

IdentifyRequest decode_identify_request(const nlohmann::json& doc);

/// A CSV body and the query of POST /api/v1/identify as the JSON request: {"csv": body, "engine", "typed":
/// {typed_*}, "request": {every other parameter, as a number when it reads as one}}.
nlohmann::json identify_request_from_csv(std::string body, const std::multimap<std::string, std::string>& query);

/// What the use case found, for the encoder.
struct IdentifyOutcome {
  Identification identification;
  std::optional<TuneResult> tuned;
  std::optional<ResponseValues> asked;        ///< the request's frequency (after any clamp) and damping ratio
  std::optional<ResponseValues> typed;        ///< as frequency and damping ratio
  std::optional<Correction> correction;
  double effective_mass = 0.0;                ///< kg, of the request
  std::size_t rounds = 0;                     ///< recordings the correction used
  const engines::EngineModel* model = nullptr;  ///< the engine's model, when it is modelled
  std::optional<engines::EngineReport> next_report;  ///< the model's report for the corrected values
};

nlohmann::json encode_identify_result(const IdentifyRequest& request, const IdentifyOutcome& outcome);

/// The sentence for a verdict (docs/identify.md).
std::string identify_verdict_message(IdentifyVerdict verdict);

}  // namespace softtune::codec

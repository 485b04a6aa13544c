#include "codec/correction_codec.h"

#include <numbers>

#include "codec/json_writer.h"
#include "softtune/softness.h"

namespace softtune::codec {

using nlohmann::json;

json response_json(const ResponseValues& v, double mass) {
  const SpringConstants s = spring_constants(mass, 2.0 * std::numbers::pi * v.frequency_hz, v.damping_ratio);
  return {{"frequency_hz", number_or_null(v.frequency_hz)}, {"damping_ratio", number_or_null(v.damping_ratio)},
          {"k", number_or_null(s.stiffness)}, {"c", number_or_null(s.damping)}};
}

std::string_view correction_verdict_name(CorrectionVerdict verdict) {
  switch (verdict) {
    case CorrectionVerdict::converging: return "converging";
    case CorrectionVerdict::met: return "met";
    case CorrectionVerdict::beyond_reach: return "beyond_reach";
    case CorrectionVerdict::stalled: return "stalled";
  }
  return "converging";
}

std::string correction_verdict_message(CorrectionVerdict verdict) {
  switch (verdict) {
    case CorrectionVerdict::converging:
      return "converging: type next, record again and send this recording as the newest of previous";
    case CorrectionVerdict::met:
      return "met: the best round is within 1 % and 0.02 of the request; keep what was typed for it (next)";
    case CorrectionVerdict::beyond_reach:
      return "beyond reach: the rounds say no typed frequency and ratio reach the request in this engine (its "
             "response stops moving, or it needs a negative damping ratio typed); next is the closest they "
             "see -- use the engine's own fields, a smaller step or a modelled engine's exact";
    case CorrectionVerdict::stalled:
      return "stalled: the last rounds did worse where the model said they would improve (the response jumps, "
             "or recordings are noisier than the bar); next repeats the best round";
  }
  return "";
}

json correction_json(const Correction& c, const ResponseValues& typed, std::size_t rounds, double mass,
                     const std::optional<engines::EngineReport>& next_report) {
  return {{"method", c.method == CorrectionMethod::secant ? "secant" : "scaled"},
          {"rounds", rounds},
          {"typed", response_json(typed, mass)},
          {"next", response_json(c.next, mass)},
          {"parameters", next_report ? engine_values_json(next_report->parameters) : json()},
          {"parameters_predicted", next_report ? engine_prediction_json(next_report->predicted) : json()},
          {"verdict", std::string(correction_verdict_name(c.verdict))},
          {"message", correction_verdict_message(c.verdict)},
          {"best_round", c.best_round},
          {"expected", {{"frequency_hz", number_or_null(c.expected.frequency_hz)},
                        {"damping_ratio", number_or_null(c.expected.damping_ratio)}}},
          {"trust_radius", number_or_null(c.trust_radius)}};
}

}  // namespace softtune::codec

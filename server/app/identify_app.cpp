#include "app/identify_app.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "codec/identify_codec.h"
#include "codec/problem.h"
#include "softtune/validation.h"

namespace softtune::app {
namespace {

// What was typed as a frequency and damping ratio: omega = sqrt(k / m), zeta = c / (2 sqrt(k m)).
ResponseValues typed_response(const codec::TypedValues& typed, double mass) {
  if (typed.response) return *typed.response;
  const Oscillator o{mass, typed.spring->stiffness, typed.spring->damping};
  return {natural_angular_frequency(o) / (2.0 * std::numbers::pi), damping_ratio_of(o)};
}

std::optional<ResponseValues> measured_response(const Identification& id) {
  if (!id.joint.frequency_hz || !id.joint.damping_ratio || !(*id.joint.frequency_hz > 0.0)) return std::nullopt;
  return ResponseValues{*id.joint.frequency_hz, *id.joint.damping_ratio};
}

// The request re-aimed at the corrected values, so a modelled engine's plain export says what to type for
// them in its own fields: standard mode, whose export is next's own k = m omega^2, c = 2 m zeta omega.
// A correction may type a negative ratio (down to kIdentifyLowestTypedRatio, where the engine damps by
// itself), which the engine models take but the tune contract's damping_ratio, [0, 1000], does not: the
// request is checked with the ratio at 0 and then carries next's. Empty when the rest leaves the contract.
std::optional<TuneRequest> retargeted(TuneRequest q, const ResponseValues& next) {
  q.response_frames.reset();
  q.oscillation.reset();
  q.mode = SoftMode::standard;
  q.frequency_hz = next.frequency_hz;
  q.damping_ratio = std::max(0.0, next.damping_ratio);
  if (validate_tune_request(q)) return std::nullopt;
  q.damping_ratio = next.damping_ratio;
  return q;
}

}  // namespace

nlohmann::json run_identify(const nlohmann::json& request) {
  const codec::IdentifyRequest q = codec::decode_identify_request(request);
  codec::IdentifyOutcome o;
  o.identification = identify(q.recording.recording);
  if (q.engine) o.model = engines::find_engine_model(*q.engine);
  if (q.tune) {
    o.tuned = tune(*q.tune);
    o.effective_mass = o.tuned->effective_mass;
    o.asked = ResponseValues{o.tuned->frequency_hz, requested_damping_ratio(*q.tune)};
    o.typed = q.typed ? typed_response(*q.typed, o.effective_mass) : *o.asked;
    std::vector<CorrectionRound> rounds;
    for (std::size_t i = 0; i < q.previous.size(); ++i) {
      const codec::PreviousRound& p = q.previous[i];
      const auto measured = p.measured ? p.measured : measured_response(identify(p.recording->recording));
      if (!measured) {
        throw codec::invalid_field("previous." + std::to_string(i),
                                   "could not be identified (no frequency and damping ratio): send its measured values");
      }
      rounds.push_back({typed_response(p.typed, o.effective_mass), *measured});
    }
    if (const auto measured = measured_response(o.identification)) {
      rounds.push_back({*o.typed, *measured});
      o.rounds = rounds.size();
      // The floor for a negative typed ratio uses the engine's step: the interval the poles were fitted per.
      const double step = o.identification.fit_interval_s > 0.0 ? o.identification.fit_interval_s : o.tuned->h;
      const double lowest = q.negative_damping ? lowest_typed_damping_ratio(o.asked->frequency_hz, step) : 0.0;
      o.correction = correct_response(*o.asked, rounds, lowest);
      if (o.model) {
        if (const auto next = retargeted(*q.tune, o.correction->next)) {
          const TuneResult next_tuned = tune(*next);
          const auto models = engines::engine_models();
          for (std::size_t i = 0; i < models.size(); ++i) {
            if (models[i] == o.model) o.next_report = next_tuned.engine_reports[i];
          }
        }
      }
    }
  }
  return codec::encode_identify_result(q, o);
}

}  // namespace softtune::app

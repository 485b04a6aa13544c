#include "app/tune_app.h"

#include "codec/tune_codec.h"

namespace softtune::app {

nlohmann::json run_tune(const nlohmann::json& request) {
  const TuneRequest q = codec::decode_tune_request(request);
  const TuneResult r = tune(q);
  nlohmann::json out = codec::encode_tune_result(q, r);
  // The closed form the page's plots compare against, from core, so the page keeps no copy of it.
  out["exact_motion"] = codec::encode_exact_motion(exact_motion(r.omega, r.damping_ratio, requested_frequency_hz(q), r.h));
  // What a 2-D constraint's effective mass is made of, term by term (the page draws it beside the bodies).
  if (q.constraint) {
    if (const auto* c2 = std::get_if<Constraint2D>(&*q.constraint)) {
      Constraint2D unit = *c2;
      unit.axis.normalize();  // as tune() does (validation keeps the axis longer than kMinAxisLength)
      out["effective_mass_check"]["terms"] = codec::encode_mass_terms(inverse_effective_mass_terms(unit));
    }
  }
  return out;
}

}  // namespace softtune::app

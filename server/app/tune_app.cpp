#include "app/tune_app.h"

#include "codec/tune_codec.h"

namespace softtune::app {

nlohmann::json run_tune(const nlohmann::json& request) {
  const TuneRequest q = codec::decode_tune_request(request);
  const TuneResult r = tune(q);
  nlohmann::json out = codec::encode_tune_result(q, r);
  // The closed form the page's plots compare against, from core, so the page keeps no copy of it.
  out["exact_motion"] = codec::encode_exact_motion(exact_motion(r.omega, r.damping_ratio, requested_frequency_hz(q), r.h));
  return out;
}

}  // namespace softtune::app

#include "app/tune_app.h"

#include "codec/tune_codec.h"

namespace softtune::app {

nlohmann::json run_tune(const nlohmann::json& request) {
  const TuneRequest q = codec::decode_tune_request(request);
  return codec::encode_tune_result(q, tune(q));
}

}  // namespace softtune::app

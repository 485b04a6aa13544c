#include "app/verify_app.h"

#include "codec/verify_codec.h"

namespace softtune::app {

nlohmann::json run_verify(const nlohmann::json& request) {
  const codec::VerifyRequest q = codec::decode_verify_request(request);
  const TuneResult tuned = tune(q.tune);
  std::vector<engines::EngineVerification> runs;
  runs.reserve(q.engines.size());
  for (const engines::RealEngine* engine : q.engines) {
    runs.push_back(engines::verify_engine(*engine, tuned, q.tune, q.options));
  }
  return codec::encode_verify_result(q, tuned, runs);
}

}  // namespace softtune::app

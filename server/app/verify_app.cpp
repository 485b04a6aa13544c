#include "app/verify_app.h"

#include "app/verify_cost.h"
#include "codec/verify_codec.h"

namespace softtune::app {

namespace {

// A request that gives an effective mass and asks for the rotating plank describes the plank itself, so
// the models see the body the engine runs (Bullet's spring divides by the body's mass, not m_eff): a
// static ground and the plank of engine_run.h, anchored `offset` off its centre, across the axis.
void describe_plank(TuneRequest& q) {
  if (!q.effective_mass) return;
  const engines::PlankGeometry plank = engines::rotating_plank(*q.effective_mass);
  Constraint2D c;
  c.body_a.is_static = true;
  c.body_b.mass = plank.mass;
  c.body_b.inertia = plank.inertia;
  c.anchor_a = {0.0, plank.offset};
  c.anchor_b = {0.0, plank.offset};
  c.axis = {1.0, 0.0};
  q.effective_mass.reset();
  q.constraint = c;
}

}  // namespace

nlohmann::json run_verify(const nlohmann::json& request) {
  codec::VerifyRequest q = codec::decode_verify_request(request);
  require_within_budget(verify_cost(q));
  if (q.options.body == engines::RunBody::rotating_plank) describe_plank(q.tune);
  const TuneResult tuned = tune(q.tune);
  std::vector<engines::EngineVerification> runs;
  runs.reserve(q.engines.size());
  for (const engines::RealEngine* engine : q.engines) {
    runs.push_back(engines::verify_engine(*engine, tuned, q.tune, q.options));
  }
  return codec::encode_verify_result(q, tuned, runs);
}

}  // namespace softtune::app

#include "app/check_cost.h"

#include <algorithm>
#include <cstdio>

#include "codec/problem.h"
#include "codec/scene_codec.h"

namespace softtune::app {

double case_work(const scene::Scene& scene, const CheckRate& rate) {
  const scene::Scene s = at_rate(scene, rate);
  std::vector<scene::MassModel> models = {s.mass_model};
  for (const scene::Expectation& e : s.expectations) {
    if (e.mass_model && scene::applies_at(e, s.world) && std::find(models.begin(), models.end(), *e.mass_model) == models.end()) {
      models.push_back(*e.mass_model);
    }
  }
  const double per_step = std::max<double>(1.0, static_cast<double>(s.bodies.size() + s.joints.size() + s.oscillators.size()));
  return static_cast<double>(scene::frame_count(s.world)) * s.world.substeps * per_step * static_cast<double>(models.size());
}

double check_work(const std::vector<CheckInput>& inputs, const CheckOptions& options) {
  double work = 0.0;
  for (const CheckInput& in : shard_inputs(inputs, options.shard)) {
    if (in.problem) continue;
    try {
      const scene::Scene s = codec::decode_scene(in.document);
      for (const CheckRate& r : check_rates(s, options)) work += case_work(s, r);
    } catch (const codec::Problem&) {
      // refused again when it runs, as that case's problem
    }
  }
  return work;
}

void require_check_budget(double work, double budget, const std::string& fields, const std::string& instead) {
  if (work <= budget) return;
  char text[320];
  std::snprintf(text, sizeof text, "the check would take about %.3g body-steps (frames x substeps x (bodies + joints), per case), more than the %.3g allowed (about %g s of one core): ask for fewer presets, scenes or rates", work, budget, budget / kCheckWorkPerSecond);
  throw codec::Problem(422, "Too much work", fields, instead.empty() ? std::string(text) : std::string(text) + "; " + instead);
}

}  // namespace softtune::app

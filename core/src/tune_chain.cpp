#include "softtune/tune_chain.h"

#include <string_view>

#include "softtune/chain_solvers.h"

namespace softtune {
namespace {

// The value of the setting called `name` of the engine model called `engine`, as the request runs it.
std::optional<double> setting(const TuneRequest& q, std::string_view engine, std::string_view name) {
  const auto models = engines::engine_models();
  for (std::size_t i = 0; i < models.size(); ++i) {
    if (models[i]->name != engine) continue;
    const engines::SettingValues& values = engine_settings_for(q, i);
    for (std::size_t j = 0; j < models[i]->settings.size() && j < values.size(); ++j) {
      if (models[i]->settings[j].name == name) return values[j];
    }
  }
  return std::nullopt;
}

// Whether the request set the setting itself (Jolt's linear damping overrides the chain's default only then).
bool set_by_request(const TuneRequest& q, std::string_view engine) {
  const auto models = engines::engine_models();
  for (std::size_t i = 0; i < models.size(); ++i) {
    if (models[i]->name == engine) return i < q.engine_settings.size() && !q.engine_settings[i].empty();
  }
  return false;
}

int count_of(const std::optional<double>& v, int fallback) { return v ? static_cast<int>(*v) : fallback; }

}  // namespace

ChainDesignRequest chain_design_request(const TuneRequest& q, const TuneResult& r) {
  ChainDesignRequest out;
  out.mass_ratio = q.chain->mass_ratio;
  out.margin = q.chain->margin;
  out.frequency_hz = r.frequency_hz;
  out.damping_ratio = r.damping_ratio;
  for (ChainSolver solver : q.chain->solvers) {
    ChainSolverSettings s;
    s.solver = solver;
    s.h = r.h;
    s.warm_start = chain_default_warm_start(solver);
    s.count = chain_default_count(solver);
    const std::string_view name = chain_solver_name(solver);
    switch (solver) {
      case ChainSolver::box2d_v2_4:
        s.count = count_of(setting(q, name, "velocityIterations"), s.count);
        break;
      case ChainSolver::box2d_v3:
        s.count = count_of(setting(q, name, "subStepCount"), s.count);
        s.warm_start = setting(q, name, "enableWarmStarting").value_or(1.0) != 0.0;
        break;
      case ChainSolver::jolt:
        s.count = count_of(setting(q, name, "numVelocitySteps"), s.count);
        s.collision_steps = count_of(setting(q, name, "collisionSteps"), 1);
        if (set_by_request(q, name)) s.linear_damping = setting(q, name, "linearDamping");
        break;
      case ChainSolver::rapier:
        s.count = count_of(setting(q, name, "numSolverIterations"), s.count) +
                  count_of(setting(q, name, "additionalSolverIterations"), 0);
        break;
    }
    out.solvers.push_back(s);
  }
  return out;
}

}  // namespace softtune

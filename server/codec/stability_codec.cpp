#include "codec/stability_codec.h"

#include <cstdio>

#include "codec/json_writer.h"
#include "codec/list_reader.h"
#include "codec/problem.h"
#include "softtune/chain_solvers.h"
#include "softtune/validation.h"

namespace softtune::codec {

using nlohmann::json;

namespace {

const char* verdict_name(Verdict v) {
  return v == Verdict::stable ? "stable" : v == Verdict::marginal ? "marginal" : "unstable";
}

}  // namespace

std::optional<std::vector<ChainSolver>> read_chain_solvers(const json* v, const std::string& field) {
  if (!v) return std::nullopt;
  std::string rule = "must be an array of 1 to 4 solver names:";
  for (ChainSolver s : kAllChainSolvers) rule += std::string(" ") + std::string(chain_solver_name(s));
  if (!v->is_array() || v->empty() || v->size() > kAllChainSolvers.size()) throw invalid_field(field, rule);
  std::vector<ChainSolver> out;
  for (std::size_t i = 0; i < v->size(); ++i) {
    const auto s = (*v)[i].is_string() ? chain_solver_from_name((*v)[i].get<std::string>()) : std::nullopt;
    if (!s) throw invalid_field(field + "." + std::to_string(i), rule);
    out.push_back(*s);
  }
  return out;
}

const char* limit_kind_name(LimitKind k) {
  return k == LimitKind::found ? "found" : k == LimitKind::none_in_range ? "none_in_range" : "unstable_at_lowest";
}

namespace {

json warnings_of(std::uint8_t flags) {
  json out = json::array();
  if (flags & kBeyondNyquist) out.push_back("beyond_nyquist");
  if (flags & kFewStepsPerPeriod) out.push_back("few_steps_per_period");
  if (flags & kExactClampedToNyquist) out.push_back("exact_clamped_to_nyquist");
  if (flags & kExactOverflowFallback) out.push_back("exact_overflow_fallback");
  if (flags & kMismatch) out.push_back("prediction_mismatch");
  return out;
}

json case_json(const SweepCase& c) {
  return {
      {"method", method_name(c.method)},
      {"family", c.family == SweepFamily::frequency_ratio ? "frequency_ratio" : "stiffness"},
      {"frequency_ratio", number_or_null(c.frequency_ratio)},
      {"damping_ratio", number_or_null(c.damping_ratio)},
      {"mass", number_or_null(c.mass)},
      {"stiffness", number_or_null(c.stiffness)},
      {"h", number_or_null(c.h)},
      {"omega_h", number_or_null(std::sqrt(c.stiffness / c.mass) * c.h)},
      {"spectral_radius", number_or_null(c.spectral_radius)},
      {"predicted", verdict_name(c.predicted)},
      {"predicted_stable", c.predicted != Verdict::unstable},
      {"observed_spectral_radius", number_or_null(c.observed_spectral_radius)},
      {"observed", verdict_name(c.observed)},
      {"observed_stable", c.observed != Verdict::unstable},
      {"warnings", warnings_of(c.warnings)},
  };
}

std::optional<Method> method_from_name(const std::string& name) {
  for (Method m : kAllMethods) {
    if (method_name(m) == name) return m;
  }
  return std::nullopt;
}

std::vector<Method> read_methods(ObjectReader& r) {
  const json* v = r.raw("methods");
  std::string rule = "must be an array of method names:";
  for (Method m : kAllMethods) rule += std::string(" ") + std::string(method_name(m));
  if (!v) return {kAllMethods.begin(), kAllMethods.end()};
  if (!v->is_array() || v->empty() || v->size() > kAllMethods.size()) throw invalid_field("methods", rule);
  std::vector<Method> out;
  for (std::size_t i = 0; i < v->size(); ++i) {
    const auto m = (*v)[i].is_string() ? method_from_name((*v)[i].get<std::string>()) : std::nullopt;
    if (!m) throw invalid_field("methods." + std::to_string(i), rule);
    out.push_back(*m);
  }
  return out;
}

void read_chain(ObjectReader& parent, StabilityRequest& q) {
  const json* v = parent.raw("chain");
  if (!v) return;
  if (v->is_boolean()) {
    q.run_chain = v->get<bool>();
    return;
  }
  if (!v->is_object()) throw invalid_field("chain", "must be true, false or an object");
  ObjectReader r = *parent.object("chain");
  ChainSweepSettings& c = q.chain;
  if (auto x = read_chain_solvers(r.raw("solvers"), "chain.solvers")) c.solvers = *x;
  if (auto x = read_number_list(r, "mass_ratios", kMaxGridEntries, 1.0, kMaxMassRatio, "")) c.mass_ratios = *x;
  if (auto x = read_integer_list(r, "iterations", kMaxGridEntries, 1, kMaxChainIterations)) c.iterations = *x;
  if (auto x = read_number_list(r, "frequency_ratios", kMaxGridEntries, 1e-6, kMaxFrequencyRatio, "")) c.frequency_ratios = *x;
  std::sort(c.frequency_ratios.begin(), c.frequency_ratios.end());
  if (auto z = r.number("damping_ratio")) {
    if (!(*z >= 0.0 && *z <= limits::kMaxDampingRatio)) throw invalid_field("chain.damping_ratio", "must be a number in [0, 1000]");
    c.damping_ratio = *z;
  }
  if (auto h = r.number("h")) {
    if (!(*h >= kMinStep && *h <= kMaxStep)) throw invalid_field("chain.h", "must be a number in [1e-9, 1] s");
    c.h = *h;
  }
  r.finish();
}

json verdict_or_null(const std::optional<Verdict>& v) { return v ? json(verdict_name(*v)) : json(nullptr); }

json chain_limit_json(const ChainLimit& l, double h) {
  std::optional<double> unstable_hz;
  if (l.lowest_unstable_frequency_ratio) unstable_hz = *l.lowest_unstable_frequency_ratio / h;
  return {{"solver", chain_solver_name(l.solver)},
          {"count_name", chain_count_name(l.solver)},
          {"count", l.count},
          {"mass_ratio", number_or_null(l.mass_ratio)},
          {"iterations", l.iterations},
          {"substeps", l.substeps},
          {"warm_start", l.warm_start},
          {"limit", limit_kind_name(l.kind)},
          {"highest_stable_frequency_ratio", number_or_null(l.highest_stable_frequency_ratio)},
          {"highest_stable_frequency_hz", number_or_null(l.highest_stable_frequency_hz)},
          {"lowest_unstable_frequency_ratio", number_or_null(l.lowest_unstable_frequency_ratio)},
          {"lowest_unstable_frequency_hz", number_or_null(unstable_hz)},
          {"scan_highest_stable_frequency_ratio", number_or_null(l.scan_highest_stable_frequency_ratio)},
          {"spectral_radius_stable_side", number_or_null(l.highest_stable_frequency_ratio ? std::optional<double>(l.stable_side_radius) : std::nullopt)},
          {"spectral_radius_unstable_side", number_or_null(l.lowest_unstable_frequency_ratio ? std::optional<double>(l.unstable_side_radius) : std::nullopt)},
          {"observed_stable_side", verdict_or_null(l.observed_stable_side)},
          {"observed_unstable_side", verdict_or_null(l.observed_unstable_side)},
          {"confirmed", l.confirmed},
          {"stable_over_whole_scan", l.stable_over_whole_scan}};
}

json step_limit_json(const StepLimit& l) {
  return {{"method", method_name(l.method)},
          {"damping_ratio", number_or_null(l.damping_ratio)},
          {"limit", limit_kind_name(l.omega_h.kind)},
          {"largest_stable_omega_h", number_or_null(l.omega_h.stable_side)},
          {"smallest_unstable_omega_h", number_or_null(l.omega_h.unstable_side)},
          {"closed_form_omega_h", number_or_null(l.closed_form_omega_h)}};
}

json chain_case_json(const ChainCase& c) {
  return {{"solver", chain_solver_name(c.solver)},
          {"count", c.count},
          {"mass_ratio", number_or_null(c.mass_ratio)},
          {"iterations", c.iterations},
          {"substeps", c.substeps},
          {"warm_start", c.warm_start},
          {"frequency_ratio", number_or_null(c.frequency_ratio)},
          {"damping_ratio", number_or_null(c.damping_ratio)},
          {"spectral_radius", number_or_null(c.spectral_radius)},
          {"predicted", verdict_name(c.predicted)},
          {"predicted_stable", c.predicted != Verdict::unstable},
          {"observed_spectral_radius", number_or_null(c.observed_spectral_radius)},
          {"observed", verdict_name(c.observed)},
          {"observed_stable", c.observed != Verdict::unstable}};
}

json chain_json(const StabilityRequest& q, const ChainSweepResult& chain) {
  json limits = json::array();
  for (const ChainLimit& l : chain.limits) limits.push_back(chain_limit_json(l, q.chain.h));
  json out = {{"damping_ratio", number_or_null(q.chain.damping_ratio)},
              {"h", number_or_null(q.chain.h)},
              {"scanned_frequency_ratios", q.chain.frequency_ratios},
              {"cases", chain.cases.size()},
              {"mismatches", chain.mismatches},
              {"limit_relative_tolerance", kLimitRelativeTolerance},
              {"unconfirmed_limits", chain.unconfirmed_limits},
              {"limits", std::move(limits)}};
  if (q.include_cases) {
    json cases = json::array();
    for (const ChainCase& c : chain.cases) cases.push_back(chain_case_json(c));
    out["case_list"] = std::move(cases);
  }
  return out;
}

}  // namespace

std::size_t grid_case_bound(const SweepSettings& s) {
  return s.methods.size() * s.steps.size() * s.masses.size() * s.damping_ratios.size() *
         (s.frequency_ratios.size() + s.stiffnesses.size());
}

StabilityRequest decode_stability_request(const json& doc) {
  StabilityRequest q;
  if (doc.is_null()) return q;
  ObjectReader r = read_object(doc, "");
  if (auto name = r.string("preset")) {
    if (name->empty() || name->size() > kMaxPresetName) throw invalid_field("preset", "must be a preset name of 1 to 64 characters");
    for (const auto& item : doc.items()) {
      // The scene engine may come with it; the app layer reads it against the scene backends.
      if (item.key() == "engine" || item.key() == "engine_settings") {
        q.preset_engine[item.key()] = item.value();
        r.raw(item.key());
        continue;
      }
      if (item.key() != "preset") throw invalid_field(item.key(), "is not allowed beside preset (a preset search runs alone)");
    }
    q.preset = *name;
    q.run_chain = false;
    r.finish();
    return q;
  }
  SweepSettings& s = q.sweep;
  s.methods = read_methods(r);
  if (auto x = read_number_list(r, "frequency_ratios", kMaxGridEntries, 1e-6, kMaxFrequencyRatio, "")) s.frequency_ratios = *x;
  if (auto x = read_number_list(r, "stiffnesses", kMaxGridEntries, 0.0, kMaxStiffness, "N/m")) s.stiffnesses = *x;
  if (auto x = read_number_list(r, "damping_ratios", kMaxGridEntries, 0.0, limits::kMaxDampingRatio, "")) s.damping_ratios = *x;
  if (auto x = read_number_list(r, "masses", kMaxGridEntries, limits::kMinMass, limits::kMaxMass, "kg")) s.masses = *x;
  if (auto x = read_number_list(r, "steps", kMaxGridEntries, kMinStep, kMaxStep, "s")) s.steps = *x;
  if (auto k = r.number("max_stiffness")) {
    if (!(*k > 0.0 && *k <= kMaxStiffness)) throw invalid_field("max_stiffness", "must be a number in (0, 1e15] N/m");
    s.max_stiffness = *k;
  }
  if (auto n = r.integer("observe_steps")) {
    if (*n < kMinObserveSteps || *n > kMaxObserveSteps) throw invalid_field("observe_steps", "must be an integer in [1000, 100000]");
    s.observe_steps = static_cast<int>(*n);
  }
  if (const json* b = r.raw("include_cases")) {
    if (!b->is_boolean()) throw invalid_field("include_cases", "must be true or false");
    q.include_cases = b->get<bool>();
  }
  read_chain(r, q);
  r.finish();
  const std::size_t cases = grid_case_bound(s);
  if (cases > kMaxCases) {
    throw invalid_field("frequency_ratios", "the grid has " + std::to_string(cases) + " cases; the limit is " +
                                                std::to_string(kMaxCases) + ": shorten the lists");
  }
  return q;
}

json encode_stability_result(const StabilityRequest& q, const SweepResult& sweep,
                              const std::optional<ChainSweepResult>& chain, const StageList& stages) {
  const SweepSummary& s = sweep.summary;
  json out;
  out["summary"] = {
      {"cases", s.cases},
      {"predicted_stable", s.predicted_stable},
      {"predicted_marginal", s.predicted_marginal},
      {"predicted_unstable", s.predicted_unstable},
      {"observed_unstable", s.observed_unstable},
      {"mismatches", s.mismatches},
      {"soft_blowups", s.soft_blowups},
      {"non_finite_values", s.non_finite_values},
      {"observe_steps", std::max(1000, q.sweep.observe_steps)},
      {"marginal_band", kMarginalBand},
      {"passed", s.mismatches == 0 && s.soft_blowups == 0 && s.non_finite_values == 0},
  };
  if (q.include_cases) {
    json cases = json::array();
    for (const SweepCase& c : sweep.cases) cases.push_back(case_json(c));
    out["cases"] = std::move(cases);
  }
  json step_limits = json::array();
  for (const StepLimit& l : sweep.step_limits) step_limits.push_back(step_limit_json(l));
  out["step_limits"] = {{"searched_omega_h", {kStepLimitLowest, kStepLimitHighest}},
                        {"limit_relative_tolerance", kLimitRelativeTolerance},
                        {"limits", std::move(step_limits)}};
  if (chain) {
    out["chain"] = chain_json(q, *chain);
    out["summary"]["passed"] =
        out["summary"]["passed"].get<bool>() && chain->mismatches == 0 && chain->unconfirmed_limits == 0;
  }
  out["stages"] = stages_json(stages);
  return out;
}

}  // namespace softtune::codec

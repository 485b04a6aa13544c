#include "codec/tune_codec.h"

#include <cmath>
#include <cstdio>
#include <span>

#include "codec/json_writer.h"
#include "codec/problem.h"
#include "codec/settings_codec.h"
#include "codec/stability_codec.h"
#include "softtune/chain_solvers.h"
#include "softtune/validation.h"

namespace softtune::codec {
namespace {

using nlohmann::json;

template <typename Body>
bool read_static(ObjectReader& parent, std::string_view key, Body& body) {
  const json* v = parent.raw(key);
  if (!v) throw invalid_field(parent.field(key), "is required: a body object or the string \"static\"");
  if (v->is_string()) {
    if (*v != "static") throw invalid_field(parent.field(key), "must be a body object or the string \"static\"");
    body.is_static = true;
    return true;
  }
  if (!v->is_object()) throw invalid_field(parent.field(key), "must be a body object or the string \"static\"");
  return false;
}

Body2D read_body_2d(ObjectReader& parent, std::string_view key) {
  Body2D b;
  if (read_static(parent, key, b)) return b;
  ObjectReader r = *parent.object(key);
  const auto mass = r.number("mass");
  if (!mass) throw invalid_field(r.field("mass"), "is required for a dynamic body (kg)");
  b.mass = *mass;
  b.inertia = r.number("inertia");
  if (auto p = r.numbers("position", 2)) b.position = {(*p)[0], (*p)[1]};
  if (auto a = r.number("angle")) b.angle = *a;
  r.finish();
  return b;
}

Eigen::Matrix3d read_inertia_3d(ObjectReader& r) {
  const json* v = r.raw("inertia");
  const std::string rule = "must be a number, 3 principal moments [Ixx, Iyy, Izz] or a 3x3 tensor (kg m^2)";
  if (v->is_number()) return Eigen::Matrix3d::Identity() * v->get<double>();
  if (!v->is_array()) throw invalid_field(r.field("inertia"), rule);
  if (v->size() == 3 && (*v)[0].is_number()) {
    const auto d = *r.numbers("inertia", 3);
    return Eigen::Vector3d(d[0], d[1], d[2]).asDiagonal();
  }
  if (v->size() != 3) throw invalid_field(r.field("inertia"), rule);
  Eigen::Matrix3d m;
  for (int i = 0; i < 3; ++i) {
    const json& row = (*v)[i];
    if (!row.is_array() || row.size() != 3) throw invalid_field(r.field("inertia"), rule);
    for (int j = 0; j < 3; ++j) {
      if (!row[j].is_number()) throw invalid_field(r.field("inertia"), rule);
      m(i, j) = row[j].get<double>();
    }
  }
  return m;
}

Body3D read_body_3d(ObjectReader& parent, std::string_view key) {
  Body3D b;
  if (read_static(parent, key, b)) return b;
  ObjectReader r = *parent.object(key);
  const auto mass = r.number("mass");
  if (!mass) throw invalid_field(r.field("mass"), "is required for a dynamic body (kg)");
  b.mass = *mass;
  if (r.has("inertia")) b.inertia = read_inertia_3d(r);
  if (auto p = r.numbers("position", 3)) b.position = {(*p)[0], (*p)[1], (*p)[2]};
  if (auto q = r.numbers("orientation", 4)) b.orientation = Eigen::Quaterniond((*q)[0], (*q)[1], (*q)[2], (*q)[3]);
  r.finish();
  return b;
}

template <int N>
Eigen::Matrix<double, N, 1> read_vector(ObjectReader& r, std::string_view key, bool required,
                                        const Eigen::Matrix<double, N, 1>& fallback) {
  auto v = r.numbers(key, N);
  if (!v) {
    if (required) throw invalid_field(r.field(key), "is required (" + std::to_string(N) + " numbers)");
    return fallback;
  }
  return Eigen::Map<const Eigen::Matrix<double, N, 1>>(v->data());
}

template <typename C, typename ReadBody>
C read_constraint(ObjectReader& r, ConstraintType type, ReadBody read_body) {
  using Vec = decltype(C::axis);
  C c;
  c.type = type;
  c.body_a = read_body(r, "body_a");
  c.body_b = read_body(r, "body_b");
  const bool linear = type == ConstraintType::linear;
  c.anchor_a = read_vector<Vec::RowsAtCompileTime>(r, "anchor_a", linear, c.body_a.position);
  c.anchor_b = read_vector<Vec::RowsAtCompileTime>(r, "anchor_b", linear, c.body_b.position);
  // 2-D angular constraints act about z: no axis needed.
  const bool axis_required = linear || Vec::RowsAtCompileTime == 3;
  c.axis = read_vector<Vec::RowsAtCompileTime>(r, "axis", axis_required, c.axis);
  return c;
}

AnyConstraint read_any_constraint(ObjectReader& r) {
  const auto dimension = r.integer("dimension");
  if (!dimension || (*dimension != 2 && *dimension != 3)) throw invalid_field(r.field("dimension"), "must be 2 or 3");
  const auto type_index = r.choice("type", {"linear", "angular"});
  const ConstraintType type = type_index.value_or(0) == 0 ? ConstraintType::linear : ConstraintType::angular;
  AnyConstraint out;
  if (*dimension == 2) {
    out = read_constraint<Constraint2D>(r, type, read_body_2d);
  } else {
    out = read_constraint<Constraint3D>(r, type, read_body_3d);
  }
  r.finish();
  return out;
}

std::string choices_text(std::span<const std::string_view> names) {
  std::string out;
  for (std::string_view n : names) out += (out.empty() ? "\"" : ", \"") + std::string(n) + "\"";
  return out;
}

// engine_settings: {"<engine>": {"<setting>": number or choice}}, each engine's object checked against its
// model's specs (codec/settings_codec.h). Unknown engines and settings are refused.
std::vector<engines::SettingValues> read_engine_settings(ObjectReader& r) {
  const json* v = r.raw("engine_settings");
  if (!v) return {};
  const std::string field = r.field("engine_settings");
  if (!v->is_object()) throw invalid_field(field, "must be an object {engine: {setting: value}}");
  const auto models = engines::engine_models();
  std::vector<std::string_view> names;
  for (const engines::EngineModel* m : models) names.push_back(m->name);
  std::vector<engines::SettingValues> out(models.size());
  for (const auto& [name, settings] : v->items()) {
    std::size_t index = 0;
    while (index < models.size() && models[index]->name != name) ++index;
    if (index == models.size()) {
      throw invalid_field(field + "." + name, "is not a modelled engine: one of " + choices_text(names));
    }
    out[index] = read_setting_values(settings, field + "." + name, models[index]->settings);
  }
  return out;
}

}  // namespace

TuneRequest read_tune_fields(ObjectReader& r) {
  TuneRequest q;
  if (auto v = r.number("fps")) q.fps = *v;
  if (auto v = r.integer("substeps")) {
    if (*v < 1 || *v > limits::kMaxSubsteps) {
      throw invalid_field(r.field("substeps"), "must be an integer in [1, " + std::to_string(limits::kMaxSubsteps) + "]");
    }
    q.substeps = static_cast<int>(*v);
  }
  q.response_frames = r.number("response_frames");
  if (auto v = r.number("basis_fps")) q.basis_fps = *v;
  q.frequency_hz = r.number("frequency_hz");
  if (auto i = r.choice("oscillation", {"free", "some", "none"})) q.oscillation = static_cast<Oscillation>(*i);
  q.damping_ratio = r.number("damping_ratio");
  if (auto i = r.choice("mode", {"standard", "exact"})) q.mode = static_cast<SoftMode>(*i);
  q.effective_mass = r.number("effective_mass");
  if (auto c = r.object("constraint")) q.constraint = read_any_constraint(*c);
  q.engine_settings = read_engine_settings(r);
  if (auto e = validate_tune_request(q)) throw invalid_field(e->field, e->rule);
  return q;
}

namespace {

// chain: {"mass_ratio": m2 / m1 in [1, 1e9] (required), "margin": [1, 10] (default 1.25), "solvers": names}
// (docs/accuracy-and-stability.md, "The design answer"). Only the tune contract reads it.
std::optional<ChainAsk> read_chain_ask(ObjectReader& parent) {
  auto o = parent.object("chain");
  if (!o) return std::nullopt;
  ObjectReader& r = *o;
  ChainAsk a;
  const auto ratio = r.number("mass_ratio");
  if (!ratio || !(*ratio >= 1.0 && *ratio <= kMaxMassRatio)) {
    throw invalid_field(r.field("mass_ratio"), "is required: a number in [1, 1e9] (the weight's mass over the link's)");
  }
  a.mass_ratio = *ratio;
  if (auto m = r.number("margin")) {
    if (!(*m >= 1.0 && *m <= kMaxChainMargin)) throw invalid_field(r.field("margin"), "must be a number in [1, 10]");
    a.margin = *m;
  }
  if (auto x = read_chain_solvers(r.raw("solvers"), r.field("solvers"))) a.solvers = *x;
  r.finish();
  return a;
}

}  // namespace

TuneRequest decode_tune_request(const json& doc) {
  ObjectReader r = read_object(doc, "");
  TuneRequest q = read_tune_fields(r);
  q.chain = read_chain_ask(r);
  r.finish();
  return q;
}

namespace {

json analysis_json(const DiscreteAnalysis& a) {
  const Eigen::Matrix2d& m = a.step_matrix;
  const char* verdict = a.verdict == Verdict::stable ? "stable" : a.verdict == Verdict::marginal ? "marginal" : "unstable";
  return {
      {"step_matrix", {{number_or_null(m(0, 0)), number_or_null(m(0, 1))}, {number_or_null(m(1, 0)), number_or_null(m(1, 1))}}},
      {"eigenvalues", {{{"re", number_or_null(a.z1.real())}, {"im", number_or_null(a.z1.imag())}},
                       {{"re", number_or_null(a.z2.real())}, {"im", number_or_null(a.z2.imag())}}}},
      {"spectral_radius", number_or_null(a.spectral_radius)},
      {"verdict", verdict},
      {"stable", a.verdict != Verdict::unstable},
      {"max_stable_h", number_or_null(a.max_stable_h)},
      {"unconditionally_stable", !a.max_stable_h.has_value()},
      {"steps_per_period", number_or_null(a.steps_per_period)},
      {"achieved_frequency_hz", number_or_null(a.achieved_frequency_hz)},
      {"achieved_damping_ratio", number_or_null(a.achieved_damping_ratio)},
      {"achieved_damped_frequency_hz", number_or_null(a.achieved_damped_frequency_hz)},
  };
}

// Each modelled engine's report joins that engine's object (docs/engines.md): what was assumed, what to type,
// what the engine does with it, and what to type so it does what was asked.
void add_engine_reports(json& engines_out, const std::vector<engines::EngineReport>& reports) {
  const auto models = engines::engine_models();
  for (std::size_t i = 0; i < models.size() && i < reports.size(); ++i) {
    const engines::EngineReport& r = reports[i];
    json& e = engines_out[std::string(models[i]->name)];
    e["model"] = models[i]->modelled;
    e["settings"] = engine_values_json(r.settings);
    e["parameters"] = engine_values_json(r.parameters);
    e["predicted"] = engine_prediction_json(r.predicted);
    e["exact"] = r.exact ? engine_values_json(*r.exact) : json();
    e["exact_predicted"] = r.exact_predicted ? engine_prediction_json(*r.exact_predicted) : json();
    e["warnings"] = warnings_json(r.warnings);
  }
}

const char* verdict_text(Verdict v) {
  return v == Verdict::stable ? "stable" : v == Verdict::marginal ? "marginal" : "unstable";
}

// The chain's design answer per solver (chain_design.h): the limit with the request's settings, and the
// fewest counts that reach margin x the asked frequency.
json chain_design_json(const ChainAsk& ask, const TuneResult& r) {
  json solvers = json::object();
  for (const ChainDesign& d : r.chain) {
    const ChainLimit& l = d.limit;
    std::optional<double> unstable_hz;
    if (l.lowest_unstable_frequency_ratio) unstable_hz = *l.lowest_unstable_frequency_ratio / d.settings.h;
    solvers[std::string(chain_solver_name(d.settings.solver))] = {
        {"count_name", chain_count_name(d.settings.solver)},
        {"count", d.settings.count},
        {"warm_start", d.settings.warm_start},
        {"limit", limit_kind_name(l.kind)},
        {"highest_stable_frequency_hz", number_or_null(l.highest_stable_frequency_hz)},
        {"lowest_unstable_frequency_hz", number_or_null(unstable_hz)},
        {"confirmed", l.confirmed},
        {"observed_stable_side", l.observed_stable_side ? json(verdict_text(*l.observed_stable_side)) : json()},
        {"observed_unstable_side", l.observed_unstable_side ? json(verdict_text(*l.observed_unstable_side)) : json()},
        {"stable_at_target", d.stable_at_target},
        {"meets_margin", d.meets_margin},
        {"fewest_count", d.fewest_count ? json(*d.fewest_count) : json()},
        {"fewest_count_highest_stable_frequency_hz", number_or_null(d.fewest_count_limit_hz)},
    };
  }
  return {{"mass_ratio", number_or_null(ask.mass_ratio)},
          {"margin", number_or_null(ask.margin)},
          {"frequency_hz", number_or_null(r.frequency_hz)},
          {"damping_ratio", number_or_null(r.damping_ratio)},
          {"h", number_or_null(r.h)},
          {"max_count_searched", kMaxDesignCount},
          {"solvers", std::move(solvers)}};
}

json engines_json(const EngineExport& e) {
  json out;
  out["box2d_v2_4"] = {{"stiffness", number_or_null(e.box2d_v2_4.stiffness)},
                       {"damping", number_or_null(e.box2d_v2_4.damping)},
                       {"b2LinearStiffness", {{"stiffness", number_or_null(e.box2d_v2_4.linear_stiffness_k)},
                                              {"damping", number_or_null(e.box2d_v2_4.linear_stiffness_c)},
                                              {"frequency_error", number_or_null(e.box2d_v2_4.linear_stiffness_frequency_error)}}}};
  out["box2d_v3"] = {{"hertz", number_or_null(e.box2d_v3.hertz)},
                     {"damping_ratio", number_or_null(e.box2d_v3.damping_ratio)},
                     {"max_hertz", number_or_null(e.box2d_v3.max_hertz)},
                     {"headroom", number_or_null(e.box2d_v3.headroom)}};
  out["jolt"] = {{"frequency_and_damping", {{"frequency", number_or_null(e.jolt.frequency_hz)},
                                            {"damping", number_or_null(e.jolt.damping_ratio)}}},
                 {"stiffness_and_damping", {{"stiffness", number_or_null(e.jolt.stiffness)},
                                            {"damping", number_or_null(e.jolt.damping)}}}};
  out["mujoco"] = {{"solref", {number_or_null(e.mujoco.solref0), number_or_null(e.mujoco.solref1)}},
                   {"form", e.mujoco.direct ? "direct" : "standard"}};
  out["ode_bullet"] = {{"erp", number_or_null(e.ode_bullet.erp)}, {"cfm", number_or_null(e.ode_bullet.cfm)}};
  out["physx"] = {{"force", {{"stiffness", number_or_null(e.physx.stiffness)}, {"damping", number_or_null(e.physx.damping)}}},
                  {"acceleration", {{"stiffness", number_or_null(e.physx.acceleration_stiffness)},
                                    {"damping", number_or_null(e.physx.acceleration_damping)}}}};
  out["rapier"] = {{"force_based", {{"stiffness", number_or_null(e.rapier.force_stiffness)},
                                    {"damping", number_or_null(e.rapier.force_damping)}}},
                   {"acceleration_based", {{"stiffness", number_or_null(e.rapier.acceleration_stiffness)},
                                           {"damping", number_or_null(e.rapier.acceleration_damping)}}}};
  return out;
}

}  // namespace

json encode_tune_result(const TuneRequest& q, const TuneResult& r) {
  const bool has_gamma = r.softness.kind == SoftnessKind::soft || r.softness.kind == SoftnessKind::rigid;
  const auto gamma = has_gamma ? std::optional<double>(r.softness.gamma) : std::nullopt;
  const auto beta = has_gamma ? std::optional<double>(r.softness.beta) : std::nullopt;
  const char* kinds[] = {"soft", "rigid", "no_constraint", "unrepresentable"};
  json out = {
      {"mode", q.mode == SoftMode::exact ? "exact" : "standard"},
      {"requested", {{"frequency_hz", number_or_null(requested_frequency_hz(q))},
                     {"damped_frequency_hz", number_or_null(requested_frequency_hz(q) *
                                                           std::sqrt(std::max(0.0, 1.0 - requested_damping_ratio(q) * requested_damping_ratio(q))))},
                     {"damping_ratio", number_or_null(requested_damping_ratio(q))}}},
      {"h", number_or_null(r.h)},
      {"frequency_hz", number_or_null(r.frequency_hz)},
      {"omega", number_or_null(r.omega)},
      {"damping_ratio", number_or_null(r.damping_ratio)},
      {"effective_mass", number_or_null(r.effective_mass)},
      {"k", number_or_null(r.spring.stiffness)},
      {"c", number_or_null(r.spring.damping)},
      {"standard", {{"k", number_or_null(r.standard_spring.stiffness)}, {"c", number_or_null(r.standard_spring.damping)}}},
      {"softness", kinds[static_cast<int>(r.softness.kind)]},
      {"gamma", number_or_null(gamma)},
      {"beta", number_or_null(beta)},
      {"erp", number_or_null(beta)},
      {"cfm", number_or_null(gamma)},
      {"gamma_impulse", gamma ? number_or_null(impulse_gamma(*gamma, r.h)) : json()},
      {"bias_factor", beta ? number_or_null(bias_factor(*beta, r.h)) : json()},
      {"box2d_v3", r.box2d_v3 ? json{{"bias_rate", number_or_null(r.box2d_v3->bias_rate)},
                                     {"mass_scale", number_or_null(r.box2d_v3->mass_scale)},
                                     {"impulse_scale", number_or_null(r.box2d_v3->impulse_scale)}}
                              : json()},
      {"achieved", {{"frequency_hz", number_or_null(r.achieved_frequency_hz)},
                    {"damping_ratio", number_or_null(r.achieved_damping_ratio)},
                    {"damped_frequency_hz", number_or_null(r.achieved_damped_frequency_hz)},
                    {"spectral_radius", number_or_null(r.achieved_spectral_radius)}}},
      {"engines", engines_json(r.engines)},
      {"warnings", warnings_json(r.warnings)},
      {"stages", stages_json(r.stages)},
  };
  if (q.constraint) {
    out["effective_mass_check"] = {{"jacobian", number_or_null(1.0 / r.effective_mass)},
                                   {"unit_impulse", number_or_null(r.inverse_effective_mass_impulse)},
                                   {"box2d_reduced_mass", number_or_null(r.box2d_reduced_mass)}};
  }
  json stability = json::object();
  for (std::size_t i = 0; i < kAllMethods.size(); ++i) {
    stability[std::string(method_name(kAllMethods[i]))] = analysis_json(r.stability[i]);
  }
  out["stability"] = std::move(stability);
  add_engine_reports(out["engines"], r.engine_reports);
  if (q.chain) out["chain"] = chain_design_json(*q.chain, r);
  return out;
}

json encode_exact_motion(const ExactMotion& m) {
  const Eigen::Matrix2d& e = m.step_matrix;
  json x = json::array();
  for (double v : m.smooth_x) x.push_back(number_or_null(v));
  return {{"duration_s", number_or_null(m.duration_s)},
          {"step_matrix", {{number_or_null(e(0, 0)), number_or_null(e(0, 1))}, {number_or_null(e(1, 0)), number_or_null(e(1, 1))}}},
          {"smooth", {{"dt_s", number_or_null(m.smooth_dt_s)}, {"x", std::move(x)}}}};
}

json encode_mass_terms(const InverseMassTerms& t) {
  return {{"body_a", {{"translational", number_or_null(t.a_translational)}, {"rotational", number_or_null(t.a_rotational)}}},
          {"body_b", {{"translational", number_or_null(t.b_translational)}, {"rotational", number_or_null(t.b_rotational)}}}};
}

}  // namespace softtune::codec

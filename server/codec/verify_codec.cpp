#include "codec/verify_codec.h"

#include <cmath>

#include "codec/json_reader.h"
#include "codec/json_writer.h"
#include "codec/problem.h"
#include "codec/tune_codec.h"

namespace softtune::codec {
namespace {

using nlohmann::json;

std::string engine_names() {
  std::string out;
  for (const engines::RealEngine* e : engines::real_engines()) out += (out.empty() ? "" : ", ") + std::string(e->name);
  return out.empty() ? "none is linked in this build" : "one of " + out;
}

std::vector<const engines::RealEngine*> read_engines(ObjectReader& r) {
  std::vector<const engines::RealEngine*> out;
  const json* v = r.raw("engines");
  if (!v) return out;
  if (!v->is_array()) throw invalid_field(r.field("engines"), "must be an array of engine names");
  if (v->size() > kVerifyMaxEngines) throw invalid_field(r.field("engines"), "must name at most 16 engines");
  for (std::size_t i = 0; i < v->size(); ++i) {
    const std::string field = r.field("engines") + "." + std::to_string(i);
    if (!(*v)[i].is_string()) throw invalid_field(field, "must be an engine name (" + engine_names() + ")");
    const std::string name = (*v)[i].get<std::string>();
    const engines::RealEngine* e = engines::find_real_engine(name);
    if (!e) {
      const bool modelled = engines::find_engine_model(name) != nullptr;
      throw invalid_field(field, modelled ? "is modelled but not linked in process (" + engine_names() +
                                                "; its real-engine test is tests/engines/" + name + ")"
                                          : "is not an engine (" + engine_names() + ")");
    }
    for (const engines::RealEngine* seen : out) {
      if (seen == e) throw invalid_field(field, "names " + name + " twice");
    }
    out.push_back(e);
  }
  return out;
}

json measured_json(const engines::Measured& m) {
  return {{"frequency_hz", number_or_null(m.frequency_hz)},
          {"damping_ratio", number_or_null(m.damping_ratio)},
          {"residual", number_or_null(m.residual)},
          {"finite", m.finite}};
}

// Relative frequency error and absolute damping-ratio error of a measurement against a reference.
json errors_json(const engines::Measured& m, std::optional<double> frequency_hz, std::optional<double> zeta) {
  const bool f = m.frequency_hz && frequency_hz && *frequency_hz > 0.0;
  const bool d = m.damping_ratio && zeta;
  return {{"frequency", f ? number_or_null(*m.frequency_hz / *frequency_hz - 1.0) : json()},
          {"damping_ratio", d ? number_or_null(*m.damping_ratio - *zeta) : json()}};
}

json trajectory_json(const engines::RunTrajectory& x, double dt) {
  const std::size_t stride = std::max<std::size_t>(1, (x.size() + kVerifyMaxPlotSamples - 1) / kVerifyMaxPlotSamples);
  json samples = json::array();
  for (std::size_t i = 0; i < x.size(); i += stride) samples.push_back(number_or_null(x[i]));
  return {{"dt", number_or_null(dt * static_cast<double>(stride))}, {"stride", stride}, {"x", std::move(samples)}};
}

}  // namespace

VerifyRequest decode_verify_request(const json& doc) {
  ObjectReader r = read_object(doc, "");
  VerifyRequest q;
  q.engines = read_engines(r);
  if (auto d = r.number("duration_s")) {
    if (!(*d > 0.0 && *d <= engines::kVerifyMaxDuration)) {
      throw invalid_field(r.field("duration_s"), "must be a number in (0, 60] s");
    }
    q.options.duration_s = *d;
  }
  if (auto b = r.choice("body", {"point", "rotating_plank"})) q.options.body = static_cast<engines::RunBody>(*b);
  if (auto x0 = r.number("x0")) {
    if (!(*x0 > 0.0 && *x0 <= 1.0)) throw invalid_field(r.field("x0"), "must be a number in (0, 1] m");
    q.options.x0 = *x0;
  }
  q.tune = read_tune_fields(r);
  r.finish();
  const double steps = q.options.duration_s * q.tune.fps * q.tune.substeps;
  if (steps > engines::kVerifyMaxSteps) {
    throw invalid_field("duration_s", "times fps times substeps must be at most 200000 steps per run");
  }
  return q;
}

json encode_verify_result(const VerifyRequest& q, const TuneResult& tuned,
                          const std::vector<engines::EngineVerification>& runs) {
  const double asked_hz = requested_frequency_hz(q.tune), asked_zeta = requested_damping_ratio(q.tune);
  json engines_out = json::object();
  json stages = stages_json(tuned.stages);
  for (const engines::EngineVerification& v : runs) {
    const std::size_t index = engines::model_index(v.engine->name);
    const engines::EngineReport& report = tuned.engine_reports[index];
    json e = {
        {"version", v.engine->version},
        {"model", engines::engine_models()[index]->modelled},
        {"settings", engine_values_json(report.settings)},
        {"parameters", engine_values_json(report.parameters)},
        {"predicted", engine_prediction_json(report.predicted)},
        {"measured", measured_json(v.measured)},
        {"measured_vs_predicted", errors_json(v.measured, report.predicted.frequency_hz, report.predicted.damping_ratio)},
        {"measured_vs_requested", errors_json(v.measured, tuned.frequency_hz, asked_zeta)},
        {"trajectory", trajectory_json(v.trajectory, tuned.h)},
        {"exact", report.exact ? engine_values_json(*report.exact) : json()},
        {"warnings", warnings_json(report.warnings)},
    };
    if (v.exact_measured && report.exact_predicted) {
      e["exact_predicted"] = engine_prediction_json(*report.exact_predicted);
      e["exact_measured"] = measured_json(*v.exact_measured);
      e["exact_measured_vs_requested"] = errors_json(*v.exact_measured, tuned.frequency_hz, asked_zeta);
      e["exact_trajectory"] = trajectory_json(*v.exact_trajectory, tuned.h);
    } else {
      e["exact_predicted"] = e["exact_measured"] = e["exact_measured_vs_requested"] = e["exact_trajectory"] = json();
    }
    engines_out[std::string(v.engine->name)] = std::move(e);
    stages.push_back("engine_" + std::string(v.engine->name));
  }
  if (!runs.empty()) stages.push_back("response_fit");
  json available = json::array();
  for (const engines::RealEngine* e : engines::real_engines()) available.push_back(e->name);
  return {
      {"requested", {{"frequency_hz", number_or_null(asked_hz)}, {"damping_ratio", number_or_null(asked_zeta)}}},
      {"mode", q.tune.mode == SoftMode::exact ? "exact" : "standard"},
      {"h", number_or_null(tuned.h)},
      {"effective_mass", number_or_null(tuned.effective_mass)},
      {"frequency_hz", number_or_null(tuned.frequency_hz)},
      {"duration_s", number_or_null(q.options.duration_s)},
      {"body", q.options.body == engines::RunBody::point ? "point" : "rotating_plank"},
      {"engines", std::move(engines_out)},
      {"available_engines", std::move(available)},
      {"warnings", warnings_json(tuned.warnings)},
      {"stages", std::move(stages)},
  };
}

}  // namespace softtune::codec
